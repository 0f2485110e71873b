// What crosses the pipe from a child: a run record encoded and decoded is the same record,
// including what the child measured (errors, observables, series) and trimmed states.
#include "run/wire.hpp"

#include <gtest/gtest.h>

namespace bb {
namespace {

/// A run record with every field the wire carries set: a diverged run with settings, errors
/// per body, observables, series and events of every kind.
RunRecord a_record_of_every_field() {
  RunRecord run;
  run.backend = "course/rk4";
  run.dt = 0.01;
  run.status = RunStatus::Diverged;
  run.reason = "energy grew";
  run.diverged_at = 2.5;
  run.steps = 250;
  run.engine_settings = {{"a", 1.5}, {"b", true}, {"c", std::string("text")}};
  run.trajectory.times = {0.0, 0.1, 0.2};
  // Times without states: a run at a dt the page does not plot.
  run.errors =
      ErrorMetrics{1.0, 2.0, 3.0, 4.0, 5.0, {{0.5, 0.25, 0.125, 4.0}, {1.0, 2.0, 3.0, 1.5}}};
  run.observables = {{"period/left", {0.44, ""}, 0.45}, {"sag", {std::nullopt, "why"}, {}}};
  run.energy = {1.0, 0.9, 0.8};
  run.distance = {0.0, 1e-3, 2e-3};
  run.summarised = true;
  run.position_scale = 12.5;
  run.trajectory.events.bodies.resize(2);
  run.trajectory.events.bodies[0].contact_times = {0.05};
  run.trajectory.events.bodies[0].post_velocity = Vec3{1.0, 2.0, 0.0};
  run.trajectory.events.bodies[0].post_normal = Vec3{0.0, -1.0, 0.0};
  run.trajectory.events.bodies[1].stop_time = 1.25;
  run.trajectory.events.bodies[1].stop_position = {2.5, 0.5, -1.0};
  run.trajectory.events.bodies[1].motion_start = {1.0, 0.5, -1.0};
  run.trajectory.events.max_stretch = 0.1;
  run.trajectory.events.bodies[0].turns[1] = {{0.5, -1.0, true}, {0.75, 1.0, false}};
  run.trajectory.events.bodies[0].hinge_crossings = {0.25, 1.5};
  run.trajectory.events.bodies[1].unresolved_contact = UnresolvedContact{0, 0.5, 2.0, 0.03};
  run.trajectory.events.crossings["time_above/ball"] = {{0.1, true}, {1.9, false}};
  run.trajectory_problem = "No space left on device";
  run.step_seconds = 0.125;
  return run;
}

TEST(Wire, ARunRecordComesBackWhole) {
  const RunRecord run = a_record_of_every_field();
  const RunRecord back = wire::decode_run(wire::encode(run));
  EXPECT_EQ(back.step_seconds, 0.125);
  EXPECT_EQ(back.backend, run.backend);
  EXPECT_EQ(back.dt, run.dt);
  EXPECT_EQ(back.status, run.status);
  EXPECT_EQ(back.reason, run.reason);
  EXPECT_EQ(back.diverged_at, run.diverged_at);
  EXPECT_EQ(back.steps, run.steps);
  EXPECT_EQ(back.engine_settings, run.engine_settings);
  EXPECT_EQ(back.trajectory.times, run.trajectory.times);
  EXPECT_TRUE(back.trajectory.states.empty());
  ASSERT_TRUE(back.errors.has_value());
  EXPECT_EQ(back.errors->position_max, 1.0);
  EXPECT_EQ(back.errors->position_rms, 2.0);
  EXPECT_EQ(back.errors->position_final, 3.0);
  EXPECT_EQ(back.errors->velocity_max, 4.0);
  EXPECT_EQ(back.errors->energy_max, 5.0);
  // Each body's errors come back in order.
  ASSERT_EQ(back.errors->bodies.size(), 2u);
  EXPECT_EQ(back.errors->bodies[0].position_rms, 0.25);
  EXPECT_EQ(back.errors->bodies[0].position_final, 0.125);
  EXPECT_EQ(back.errors->bodies[1].position_max, 1.0);
  EXPECT_EQ(back.errors->bodies[1].velocity_max, 1.5);
  ASSERT_EQ(back.observables.size(), 2u);
  EXPECT_EQ(back.observables[0].name, "period/left");
  EXPECT_EQ(back.observables[0].measured.value, 0.44);
  EXPECT_EQ(back.observables[0].reference, 0.45);
  EXPECT_FALSE(back.observables[1].measured.value.has_value());
  EXPECT_EQ(back.observables[1].measured.note, "why");
  EXPECT_FALSE(back.observables[1].reference.has_value());
  EXPECT_EQ(back.energy, run.energy);
  EXPECT_EQ(back.distance, run.distance);
  EXPECT_TRUE(back.summarised);
  EXPECT_EQ(back.position_scale, 12.5);
  EXPECT_EQ(back.trajectory.events.bodies.at(0).contact_times, std::vector<double>{0.05});
  EXPECT_FALSE(back.trajectory.events.bodies.at(0).stop_time.has_value());
  EXPECT_EQ(back.trajectory.events.bodies.at(0).post_velocity, Vec3(1.0, 2.0, 0.0));
  EXPECT_EQ(back.trajectory.events.bodies.at(0).post_normal, Vec3(0.0, -1.0, 0.0));
  EXPECT_EQ(back.trajectory.events.bodies.at(1).stop_time, 1.25);
  EXPECT_EQ(back.trajectory.events.bodies.at(1).stop_position, Vec3(2.5, 0.5, -1.0));
  EXPECT_EQ(back.trajectory.events.bodies.at(1).motion_start, Vec3(1.0, 0.5, -1.0));
  EXPECT_EQ(back.trajectory.events.max_stretch, 0.1);
  const std::vector<Crossing>& crossings = back.trajectory.events.crossings.at("time_above/ball");
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_EQ(crossings[0].time, 0.1);
  EXPECT_TRUE(crossings[0].rising);
  EXPECT_EQ(crossings[1].time, 1.9);
  EXPECT_FALSE(crossings[1].rising);
  const std::vector<Turn>& turns = back.trajectory.events.bodies.at(0).turns[1];
  ASSERT_EQ(turns.size(), 2u);
  EXPECT_EQ(turns[1].time, 0.75);
  EXPECT_EQ(turns[1].position, 1.0);
  EXPECT_TRUE(turns[0].lowest && !turns[1].lowest);
  EXPECT_EQ(back.trajectory.events.bodies.at(0).hinge_crossings, std::vector<double>({0.25, 1.5}));
  const auto& pushed = back.trajectory.events.bodies.at(1).unresolved_contact;
  ASSERT_TRUE(pushed);
  EXPECT_EQ(pushed->other, 0);
  EXPECT_EQ(pushed->approach_least, 0.03);
  // Why its trajectory file could not be written, from the child that wrote it.
  EXPECT_EQ(back.trajectory_problem, run.trajectory_problem);
}

TEST(Wire, StatesOfAFewBodiesComeBack) {
  RunRecord run;
  run.trajectory.times = {0.0, 0.5};
  run.trajectory.states = {State(2), State(2)};
  run.trajectory.states[1][1].position = {1.0, 2.0, 3.0};
  run.trajectory.states[1][1].orientation = Quat(0.5, 0.5, 0.5, 0.5);
  run.trajectory.states[1][1].turn = -41.5;
  const RunRecord back = wire::decode_run(wire::encode(run));
  ASSERT_EQ(back.trajectory.states.size(), 2u);
  ASSERT_EQ(back.trajectory.states[1].size(), 2u);
  EXPECT_EQ(back.trajectory.states[1][1].position, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(back.trajectory.states[1][1].orientation.coeffs(), Quat(0.5, 0.5, 0.5, 0.5).coeffs());
  EXPECT_EQ(back.trajectory.states[1][1].turn, -41.5);
  EXPECT_FALSE(back.errors.has_value());
  EXPECT_FALSE(back.summarised);
}

TEST(Wire, ABackendsTimingsComeBackInOrder) {
  const std::vector<Timing> timings = {{0.5, 3, 100, 0.4, 0.9, 1.25, 3},
                                       {1e-6, 30, 7, 8e-7, 3e-6, 2e-5, 1}};
  const std::vector<Timing> back = wire::decode_timings(wire::encode(timings));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].median_seconds, 1e-6);
  EXPECT_EQ(back[1].repeats, 30);
  EXPECT_EQ(back[1].calls_timed, 7);
  EXPECT_EQ(back[1].min_seconds, 8e-7);
  EXPECT_EQ(back[1].max_seconds, 3e-6);
  EXPECT_EQ(back[1].timed_seconds, 2e-5);
  EXPECT_EQ(back[1].builds, 1);
  EXPECT_EQ(back[0].builds, 3);
  EXPECT_EQ(back[0].median_seconds, 0.5);
}

TEST(Wire, AStabilityTrialComesBackWhole) {
  const StabilityTrial back =
      wire::decode_trial(wire::encode(StabilityTrial{true, "energy drifts", "drift", 0.5}));
  EXPECT_TRUE(back.stable);
  EXPECT_EQ(back.reason, "energy drifts");
  EXPECT_EQ(back.growth, "drift");
  EXPECT_EQ(back.step_seconds, 0.5);
}

}  // namespace
}  // namespace bb
