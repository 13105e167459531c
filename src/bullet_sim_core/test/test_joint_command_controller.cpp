// JointCommandController on a one-joint plant (inertia J, a load torque, semi-implicit Euler as
// Bullet integrates): the held force, the position and velocity PIDs, their sum, reset and limits.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "bullet_sim_core/joint_command_controller.h"

namespace bullet_sim {
namespace {

const double kDt = 0.001;
const double kInertia = 0.0626;  // the physics tests' pendulum about its hinge: 1 kg at 0.25 m

struct Plant {
  double q = 0.0, qd = 0.0;
  std::function<double(double, double)> load = [](double, double) { return 0.0; };  // N m at (q, qd)
  // One step under the controller's effort; returns the effort applied.
  double step(JointCommandController& controller) {
    const double effort = controller.effort(q, qd, kDt);
    qd += (effort + load(q, qd)) / kInertia * kDt;
    q += qd * kDt;
    return effort;
  }
  void run(JointCommandController& controller, double seconds) {
    for (int k = 0; k < static_cast<int>(std::lround(seconds / kDt)); ++k) step(controller);
  }
};

JointCommand force(double f) {
  JointCommand c;
  c.force = f;
  return c;
}

PidTarget pid(double target, double p, double i, double d) {
  PidTarget t;
  t.target = target;
  t.gains.p = p;
  t.gains.i = i;
  t.gains.d = d;
  return t;
}

JointCommand position(const PidTarget& t) {
  JointCommand c;
  c.position = t;
  return c;
}

JointCommand velocity(const PidTarget& t) {
  JointCommand c;
  c.velocity = t;
  return c;
}

JointCommand reset() {
  JointCommand c;
  c.reset = true;
  return c;
}

TEST(JointCommandController, AForceIsHeldEveryStepUntilChangedOrReset) {
  JointCommandController controller;
  EXPECT_FALSE(controller.active());
  controller.command(force(0.2));
  EXPECT_TRUE(controller.active());
  Plant plant;
  for (int k = 0; k < 5000; ++k) ASSERT_EQ(plant.step(controller), 0.2) << "step " << k;
  // Nothing else acts: the joint has accelerated at F / J the whole time.
  EXPECT_NEAR(plant.qd, 0.2 / kInertia * 5.0, 1e-9);
  controller.command(force(-0.05));
  EXPECT_EQ(plant.step(controller), -0.05);
  controller.command(reset());
  EXPECT_FALSE(controller.active());
  EXPECT_EQ(plant.step(controller), 0.0);
}

TEST(JointCommandController, APositionPdSettlesWhereItsPullMeetsTheLoad) {
  // A constant load L (gravity on a horizontal arm, say) against p and d: the PD stops where
  // p * (target - q) = -L, so at q = target + L / p; the tolerance follows from the gains.
  const double load = -1.0, p = 20.0, d = 2.0, target = 0.5;
  JointCommandController controller;
  controller.command(position(pid(target, p, 0.0, d)));
  Plant plant;
  plant.load = [&](double, double) { return load; };
  plant.run(controller, 3.0);  // damping ratio d / (2 sqrt(p J)) = 0.89: settled in well under 1 s
  EXPECT_NEAR(plant.q, target + load / p, 1e-9);
  EXPECT_NEAR(plant.qd, 0.0, 1e-9);
}

TEST(JointCommandController, APositionPidReachesItsTargetAgainstTheLoad) {
  const double load = -1.0, target = 0.5;
  PidTarget t = pid(target, 20.0, 40.0, 2.0);
  t.gains.i_max = 5.0;  // room for the integral to carry the load
  t.gains.i_min = -5.0;
  JointCommandController controller;
  controller.command(position(t));
  Plant plant;
  plant.load = [&](double, double) { return load; };
  plant.run(controller, 8.0);  // the slowest pole of J s^3 + d s^2 + p s + i is at -2.6 per s: e^-21 of 0.05 left
  EXPECT_NEAR(plant.q, target, 1e-5);
  // A new target keeps the integral that carries the load.
  t.target = 0.6;
  controller.command(position(t));
  plant.run(controller, 6.0);
  EXPECT_NEAR(plant.q, 0.6, 1e-5);
}

TEST(JointCommandController, AVelocityPidReachesItsTarget) {
  // Viscous damping b: P alone settles at v = p vt / (p + b); with an integral term at vt.
  const double b = 0.5, p = 2.0, target = 3.0;
  JointCommandController controller;
  controller.command(velocity(pid(target, p, 0.0, 0.0)));
  Plant plant;
  plant.load = [&](double, double qd) { return -b * qd; };
  plant.run(controller, 2.0);  // time constant J / (p + b) = 25 ms
  EXPECT_NEAR(plant.qd, p * target / (p + b), 1e-9);
  controller.command(velocity(pid(target, p, 5.0, 0.0)));
  plant.run(controller, 5.0);
  EXPECT_NEAR(plant.qd, target, 1e-4);
}

TEST(JointCommandController, ForcePositionAndVelocityAddUp) {
  JointCommandController all, only_force, only_position, only_velocity;
  JointCommand c;
  c.force = 0.3;
  c.position = pid(1.0, 4.0, 1.0, 0.5);
  c.velocity = pid(-2.0, 0.7, 0.2, 0.0);
  all.command(c);
  only_force.command(force(0.3));
  only_position.command(position(*c.position));
  only_velocity.command(velocity(*c.velocity));
  for (int k = 0; k < 100; ++k) {
    const double q = 0.01 * k, qd = std::sin(0.1 * k);
    const double sum = only_force.effort(q, qd, kDt) + only_position.effort(q, qd, kDt) +
                       only_velocity.effort(q, qd, kDt);
    ASSERT_NEAR(all.effort(q, qd, kDt), sum, 1e-12) << "step " << k;
  }
}

TEST(JointCommandController, ResetDropsEveryCommandAndWhatFollowsStartsAfresh) {
  JointCommandController controller;
  JointCommand c;
  c.force = 0.3;
  c.position = pid(1.0, 4.0, 1.0, 0.5);
  c.velocity = pid(-2.0, 0.7, 0.2, 0.0);
  controller.command(c);
  Plant plant;
  plant.run(controller, 0.5);
  controller.command(reset());
  EXPECT_FALSE(controller.active());
  EXPECT_FALSE(controller.force() || controller.position() || controller.velocity());
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(plant.step(controller), 0.0);
  // Reset and a new force in one command: only the force is held; the old PIDs' integrals are gone.
  JointCommand again = force(0.1);
  again.reset = true;
  controller.command(c);
  plant.run(controller, 0.5);  // the PIDs' integrals grow
  controller.command(again);
  EXPECT_TRUE(controller.force() && !controller.position() && !controller.velocity());
  controller.command(position(pid(plant.q, 0.0, 1.0, 0.0)));
  EXPECT_NEAR(controller.effort(plant.q, 0.0, kDt), 0.1, 1e-12);  // a fresh integral: no leftover
}

TEST(JointCommandController, TheEffortLimitBoundsEachPartAndTheSum) {
  JointCommandController controller(2.0);
  controller.command(force(10.0));
  EXPECT_EQ(controller.effort(0.0, 0.0, kDt), 2.0);
  controller.command(position(pid(0.0, 1000.0, 0.0, 0.0)));
  EXPECT_EQ(controller.effort(1.0, 0.0, kDt), 0.0);   // the PID pulls -1000, held to -2: 2 - 2
  EXPECT_EQ(controller.effort(-1.0, 0.0, kDt), 2.0);  // 2 + 2, held to 2
  JointCommandController unlimited(0.0);              // URDF's effort 0: no limit
  unlimited.command(force(10.0));
  EXPECT_EQ(unlimited.effort(0.0, 0.0, kDt), 10.0);
}

TEST(JointCommandController, EachPidStaysWithinItsCommandBounds) {
  PidTarget t = pid(0.0, 1000.0, 0.0, 0.0);
  t.gains.cmd_max = 0.5;
  t.gains.cmd_min = -0.25;
  JointCommandController controller;
  controller.command(position(t));
  EXPECT_EQ(controller.effort(-1.0, 0.0, kDt), 0.5);
  EXPECT_EQ(controller.effort(1.0, 0.0, kDt), -0.25);
  JointCommand c = velocity(t);
  c.force = 1.0;  // the force is not bounded by the PID's bounds
  controller.command(c);
  EXPECT_EQ(controller.effort(0.0, 1.0, kDt), 1.0 - 0.25);  // position on target: 0
}

TEST(JointCommandController, ValidateNamesTheFieldThatIsNotANumber) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validate(force(0.5)), "");
  EXPECT_EQ(validate(force(nan)), "force: expected a finite number, got nan");
  PidTarget t = pid(0.0, 1.0, 0.0, 0.0);
  t.gains.cmd_max = inf;  // an infinite bound is no bound
  EXPECT_EQ(validate(position(t)), "");
  t.gains.p = -inf;
  EXPECT_EQ(validate(position(t)), "position.p: expected a finite number, got -inf");
  t.gains.p = 1.0;
  t.gains.i_min = nan;
  EXPECT_EQ(validate(velocity(t)), "velocity.i_min: expected a number (infinite is no bound), got nan");
  t.gains.i_min = 0.0;
  t.target = inf;
  EXPECT_EQ(validate(velocity(t)), "velocity.target: expected a finite number, got inf");
}

}  // namespace
}  // namespace bullet_sim
