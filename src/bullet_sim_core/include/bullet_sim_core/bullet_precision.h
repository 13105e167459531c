#pragma once
// Our library is built against Debian's double-precision Bullet (libBullet*-float64). Code that
// includes Bullet's headers without BT_USE_DOUBLE_PRECISION would see a different btScalar and
// corrupt memory at run time; stop it at compile time instead. find_package(catkin COMPONENTS
// bullet_sim_core) adds the define (cmake/bullet_sim_core-extras.cmake).
#ifndef BT_USE_DOUBLE_PRECISION
#error "bullet_sim_core uses double-precision Bullet: compile with -DBT_USE_DOUBLE_PRECISION"
#endif
