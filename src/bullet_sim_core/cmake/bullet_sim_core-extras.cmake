# What every package that includes bullet_sim_core's headers needs besides them:
# - Bullet in double precision: BT_USE_DOUBLE_PRECISION changes btScalar, so all of them must agree
#   (bullet_sim_core's headers refuse to compile without it);
# - Bullet's and Eigen's headers, as SYSTEM headers so that -Wall -Wextra stays quiet about them.
add_definitions(-DBT_USE_DOUBLE_PRECISION)
find_package(Eigen3 REQUIRED)
find_path(BULLET_SIM_CORE_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet)
if(NOT BULLET_SIM_CORE_BULLET_INCLUDE_DIR)
  message(FATAL_ERROR "bullet_sim_core: Bullet's headers (btBulletDynamicsCommon.h) not found: apt-get install libbullet-dev")
endif()
include_directories(SYSTEM ${BULLET_SIM_CORE_BULLET_INCLUDE_DIR} ${EIGEN3_INCLUDE_DIR})
set(BULLET_SIM_CORE_BULLET_LIBRARIES BulletDynamics-float64 BulletCollision-float64 LinearMath-float64)
# Our headers inline Bullet code, so dependents link Bullet too (this file is read after catkin
# has set bullet_sim_core_LIBRARIES).
list(APPEND bullet_sim_core_LIBRARIES ${BULLET_SIM_CORE_BULLET_LIBRARIES})
