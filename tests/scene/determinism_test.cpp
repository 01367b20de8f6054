// The same run twice gives the same bytes, on stdout and in the CSV.
#include <gtest/gtest.h>

#include <sstream>

#include "cli_support.h"
#include "particles/scenefile.h"

namespace particles::test {
namespace {

TEST(Determinism, SameSceneSameBytes) {
  const TempDir dir;
  for (const char* name : {"ball_in_box.json", "density_and_inertia.json", "no_slip_walls.json"}) {
    std::string out[2], csv[2];
    for (int run = 0; run < 2; ++run) {
      const std::string file = dir.file("run" + std::to_string(run) + ".csv").string();
      const CliResult r =
          runCli("run " + shellQuote(sceneFile(name)) + " --csv " + shellQuote(file));
      ASSERT_EQ(r.status, 0) << r.err;
      out[run] = r.out;
      csv[run] = readFile(file);
    }
    EXPECT_FALSE(out[0].empty());
    EXPECT_EQ(out[0], out[1]) << name;
    EXPECT_GT(csv[0].size(), 1000u);
    EXPECT_TRUE(csv[0] == csv[1]) << name;
  }
}

TEST(Determinism, InProcessMatchesTheBinary) {
  const SceneDef scene = loadScene(sceneFile("ball_in_box.json"));
  World world(scene);
  world.run(scene.stepCount());
  const CliResult r = runCli("run " + shellQuote(sceneFile("ball_in_box.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(finalStateText(world) + "\n", r.out);
}

TEST(Output, CsvRowsRoundTrip) {
  SceneDef scene;
  BallDef b;
  b.position = Vec2(0.1, 1.0 / 3.0);
  b.velocity = Vec2(-2.5e-300, 7);
  b.angularVelocity = 0.7;
  scene.balls = {b};
  World world(scene);
  std::ostringstream out;
  CsvTrajectoryWriter csv(out);
  csv.write(world);
  EXPECT_EQ(out.str(),
            "t,id,x,y,angle,vx,vy,omega\n0,0,0.1,0.3333333333333333,0,-2.5e-300,7,0.7\n");
}

TEST(Output, FinalStateShape) {
  SceneDef scene;
  scene.balls.resize(2);
  scene.balls[1].position = Vec2(3, 0);
  World world(scene);
  EXPECT_EQ(finalStateText(world),
            R"({"time":0.0,"balls":[{"position":[0.0,0.0],"velocity":[0.0,0.0],"angle":0.0,)"
            R"("angular_velocity":0.0},{"position":[3.0,0.0],"velocity":[0.0,0.0],"angle":0.0,)"
            R"("angular_velocity":0.0}]})");
  const nlohmann::json state = finalStateJson(world);
  EXPECT_EQ(state["time"], 0.0);
  EXPECT_EQ(state["balls"][1]["position"], nlohmann::json({3.0, 0.0}));
  EXPECT_EQ(state.size(), 2u);
  EXPECT_EQ(state["balls"][0].size(), 4u);
  EXPECT_TRUE(allFinite(world));
}

}  // namespace
}  // namespace particles::test
