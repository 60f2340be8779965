// Contact forces in the viewer (docs/contact.md, "Seeing it"): `sinew simulate --export` draws
// contacts.sto as arrows, `sinew export --contacts` draws a contacts.sto again and `sinew render
// --contacts` draws one frame of it; a ball at rest has an arrow of its weight from its contact
// point on the floor, the floor being the model's ContactHalfSpace (or --ground-plane).
#include <gtest/gtest.h>
#include <sinew/io/storage.h>
#include <sinew/viz/image.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test_util.h"
#include "engine/test_models.h"
#include "viz/glb_test_util.h"

namespace sinew {
namespace {

using testing::CliRun;
using viz::testing::ParsedGlb;

const std::string kData = SINEW_TEST_DATA_DIR;
const std::string kBall = kData + "/sinew/ball_on_floor.osim";
const std::string kSmoothBall = kData +
                                "/opensim-org/opensim-core/OpenSim/Simulation/Test/"
                                "BouncingBall_SmoothSphereHalfSpace.osim";
constexpr double kWeight = 9.80665;  // the 1 kg ball's, N

// One arrow's track, per frame: its start (m) and its force (N) from the drawn length along the
// arrow's turned +y (what the viewer shows).
struct ArrowTrack {
  std::vector<Vec3> start, force;
};

// The channel outputs of `node`'s `path` (frame by frame).
std::vector<float> Channel(const ParsedGlb& glb, int node, const std::string& path) {
  const nlohmann::json& animation = glb.doc["animations"][0];
  for (const nlohmann::json& c : animation["channels"]) {
    if (c["target"]["node"] == node && c["target"]["path"] == path) {
      const int sampler = c["sampler"];
      return viz::testing::ReadFloatAccessor(glb, animation["samplers"][sampler]["output"]);
    }
  }
  ADD_FAILURE() << "no " << path << " channel for node " << node;
  return {};
}

ArrowTrack ReadArrow(const ParsedGlb& glb, int node) {
  const double metres_per_newton =
      glb.doc["scenes"][0]["extras"]["contact_arrows"]["metres_per_newton"];
  const int head = glb.doc["nodes"][node]["children"][1];
  const std::vector<float> start = Channel(glb, node, "translation");
  const std::vector<float> rotation = Channel(glb, node, "rotation");
  const std::vector<float> scale = Channel(glb, node, "scale");
  const std::vector<float> head_at = Channel(glb, head, "translation");
  const std::vector<float> head_size = Channel(glb, head, "scale");
  ArrowTrack track;
  for (size_t k = 0; 3 * k + 2 < start.size(); ++k) {
    track.start.emplace_back(start[3 * k], start[3 * k + 1], start[3 * k + 2]);
    const Quat q(rotation[4 * k + 3], rotation[4 * k], rotation[4 * k + 1], rotation[4 * k + 2]);
    const double length = scale[3 * k + 1] * (head_at[3 * k + 1] + head_size[3 * k + 1]);
    track.force.push_back(q.normalized() * Vec3::UnitY() * (length / metres_per_newton));
  }
  return track;
}

class ExportContactsTest : public testing::CliTest {
 protected:
  // ball_on_floor.osim with its floor (the ContactHalfSpace on ground) at y = `height`.
  std::string BallWithFloorAt(double height) const {
    std::string text = testing::ReadText(kBall);
    const std::string socket = "<socket_frame>/ground</socket_frame>";
    text.insert(text.find(socket) + socket.size(),
                "<location>0 " + std::to_string(height) + " 0</location>");
    const std::string copy = Path("ball.osim");
    std::ofstream(copy) << text;
    return copy;
  }
  ParsedGlb ReadGlb(const std::string& name) const {
    return viz::testing::ParseGlb(viz::ReadFileBytes(Path(name)));
  }
  // `sinew export MODEL --states DIR/out/states.sto --contacts DIR/out/contacts.sto` draws, from
  // the files, the same one arrow (the group found by the body's name) as `rest` at the end.
  void ExpectTheSameArrowFromTheFiles(const std::string& model, const ArrowTrack& track) const {
    const CliRun again =
        Run("export " + model + " --states " + Path("out/states.sto") + " --contacts " +
            Path("out/contacts.sto") + " -o " + Path("again.glb"));
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const ParsedGlb other = ReadGlb("again.glb");
    const nlohmann::json& arrows = other.doc["scenes"][0]["extras"]["contact_arrows"];
    ASSERT_EQ(arrows["arrows"].size(), 1u);
    EXPECT_EQ(arrows["arrows"][0]["body"], 1);
    const ArrowTrack same = ReadArrow(other, arrows["arrows"][0]["node"]);
    ASSERT_EQ(same.force.size(), track.force.size());
    EXPECT_NEAR((same.force.back() - track.force.back()).norm(), 0.0, 1e-5 * kWeight);
    EXPECT_NEAR((same.start.back() - track.start.back()).norm(), 0.0, 1e-6);
  }
  // `sinew simulate MODEL OPTIONS --quiet --out DIR/out --export DIR/ball.glb`, checked to succeed.
  ParsedGlb SimulateAndExport(const std::string& model, const std::string& options) const {
    const CliRun run = Run("simulate " + model + " " + options + " --quiet --out " + Path("out") +
                           " --export " + Path("ball.glb"));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return ReadGlb("ball.glb");
  }
};

// The ball (r = 0.1 m, centre 0.3 m above ground) falls 0.3 m onto its floor at y = -0.1 and
// settles through SMC (as SimulateCollisionTest: implicit Euler at 1e-4 s, 1.5 s). At rest
// contacts.sto carries the weight to 1e-4; the arrow drawn from it is the weight, straight up,
// from the floor under the ball's centre (the line of action crosses the floor there, within
// the Hertz dent).
TEST_F(ExportContactsTest, BallAtRestHasAnArrowOfItsWeightFromItsContactOnTheFloor) {
  const std::string model = BallWithFloorAt(-0.1);
  const ParsedGlb glb = SimulateAndExport(
      model, "--collision --integrator implicit-euler --step 1e-4 --duration 1.5");
  ASSERT_FALSE(HasFailure());
  const nlohmann::json& extras = glb.doc["scenes"][0]["extras"];
  EXPECT_NEAR(extras["floor"]["point"][1].get<double>(), -0.1, 1e-12);
  EXPECT_NEAR(extras["floor"]["normal"][1].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(extras["floor"]["source"], "ContactHalfSpace floor");
  const nlohmann::json& arrows = extras["contact_arrows"];
  EXPECT_NEAR(arrows["body_weight"].get<double>(), kWeight, 1e-12);
  ASSERT_EQ(arrows["arrows"].size(), 1u);  // the ball's; the floor's reaction is not drawn
  EXPECT_EQ(arrows["arrows"][0]["name"], "smc_contact.ball");
  EXPECT_EQ(arrows["arrows"][0]["body"], 1);
  const ArrowTrack track = ReadArrow(glb, arrows["arrows"][0]["node"]);
  const auto contacts = engine::testing::ReadStoColumns(Path("out/contacts.sto"));
  ASSERT_EQ(track.force.size(), contacts.at("time").size());
  // In the air at first: no arrow.
  EXPECT_EQ(track.force.front().norm(), 0.0);
  // At rest: the weight (contacts.sto's own accuracy is 1e-4; floats keep 1e-6).
  const Vec3 rest = track.force.back();
  EXPECT_NEAR(rest.y(), kWeight, 1e-4 * kWeight);
  EXPECT_NEAR(rest.y(), contacts.at("smc_contact.ball.force.Y").back(), 1e-5 * kWeight);
  EXPECT_NEAR(std::hypot(rest.x(), rest.z()), 0.0, 1e-6);
  EXPECT_NEAR(track.start.back().y(), -0.1, 1e-6);
  EXPECT_NEAR(track.start.back().x(), 0.0, 1e-6);
  EXPECT_NEAR(track.start.back().z(), 0.0, 1e-6);

  ExpectTheSameArrowFromTheFiles(model, track);
}

// The same ball settling through NSC (`--contact nsc`, its default 1 ms step): contacts.sto's
// nsc_contact.ball group is drawn like SMC's. At rest the solver's tolerance (1e-6 m/s on the
// contact velocities) holds the ball's speed within 1e-6 m/s at both ends of a step, so the
// step's impulse is m g h to m 2e-6 m/s and the force (impulse / h) is the weight to 2e-3 N and
// its sideways part below 2e-3 N; such a friction force at the 0.1 m radius moves the line of
// action by at most 2e-4 N m / m g = 2e-5 m from the centre. The floats of the .glb keep 1e-5
// of the weight and 1e-6 m.
TEST_F(ExportContactsTest, NscBallAtRestHasAnArrowOfItsWeightFromItsContactOnTheFloor) {
  const std::string model = BallWithFloorAt(-0.1);
  const ParsedGlb glb = SimulateAndExport(model, "--collision --contact nsc --duration 1.5");
  ASSERT_FALSE(HasFailure());
  const nlohmann::json& arrows = glb.doc["scenes"][0]["extras"]["contact_arrows"];
  ASSERT_EQ(arrows["arrows"].size(), 1u);  // the ball's; ground's reaction is not drawn
  EXPECT_EQ(arrows["arrows"][0]["name"], "nsc_contact.ball");
  EXPECT_EQ(arrows["arrows"][0]["body"], 1);
  const ArrowTrack track = ReadArrow(glb, arrows["arrows"][0]["node"]);
  const auto contacts = engine::testing::ReadStoColumns(Path("out/contacts.sto"));
  const auto states = engine::testing::ReadStoColumns(Path("out/states.sto"));
  const std::vector<double>& time = contacts.at("time");
  ASSERT_EQ(track.force.size(), time.size());
  // In the air (it lands after sqrt(2 0.2 m / g) = 0.2 s): no arrow.
  for (size_t k = 0; k < time.size() && time[k] < 0.15; ++k) {
    EXPECT_EQ(track.force[k].norm(), 0.0) << "t = " << time[k];
  }
  const Vec3 rest = track.force.back();
  EXPECT_NEAR(rest.y(), kWeight, 2e-3 + 1e-5 * kWeight);
  EXPECT_NEAR(rest.y(), contacts.at("nsc_contact.ball.force.Y").back(), 1e-5 * kWeight);
  EXPECT_NEAR(std::hypot(rest.x(), rest.z()), 0.0, 2e-3 + 1e-5 * kWeight);
  const Vec3 centre(states.at("/jointset/free/tx/value").back(),
                    states.at("/jointset/free/ty/value").back(),
                    states.at("/jointset/free/tz/value").back());
  EXPECT_NEAR(track.start.back().y(), -0.1, 1e-6);
  EXPECT_NEAR(track.start.back().x(), centre.x(), 2e-5 + 1e-6);
  EXPECT_NEAR(track.start.back().z(), centre.z(), 2e-5 + 1e-6);
  ExpectTheSameArrowFromTheFiles(model, track);
}

// The pixels of `image` that pass `is`, as (x, y).
template <typename Test>
std::vector<std::pair<int, int>> PixelsWhere(const viz::Image& image, Test is) {
  std::vector<std::pair<int, int>> found;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* px = image.At(x, y);
      if (is(px[0], px[1], px[2])) found.emplace_back(x, y);
    }
  }
  return found;
}

bool IsGreen(int r, int g, int b) { return g > r + 40 && g > b + 40; }
bool IsOrange(int r, int g, int b) { return r > g + 40 && r > b + 80; }  // the contact sphere

// `sinew render --contacts` draws the arrow of the shown time, as the viewer does. The NSC ball
// at rest on its floor at y = -0.1, seen from the front (8.5 degrees above): the arrow is the
// only change to the picture, it stands on the ball's lowest point (its contact with the floor)
// under its centre and, the weight being drawn half as long as the first pose's largest side
// (the ball's 0.2 m diameter), it reaches the centre: one radius up (times cos 8.5 deg = 0.99).
// In the air (t = 0.1 s) there is no force and the picture is the plain one.
TEST_F(ExportContactsTest, RenderDrawsTheArrowOfTheShownTimeFromTheContactPoint) {
  const std::string model = BallWithFloorAt(-0.1);
  const CliRun run = Run("simulate " + model +
                         " --collision --contact nsc --duration 1.5 --quiet --out " + Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto render = [&](const std::string& options) {
    const std::string png = Path("ball.png");
    const CliRun r =
        Run("render " + model + " --states " + Path("out/states.sto") +
            " --vis primitives --view front --width 800 --height 800 " + options + " --out " + png);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return viz::DecodePng(viz::ReadFileBytes(png), png);
  };
  const std::string contacts = " --contacts " + Path("out/contacts.sto");
  const viz::Image plain = render("--time 1.5");
  const viz::Image arrow = render("--time 1.5" + contacts);
  ASSERT_FALSE(HasFailure());
  EXPECT_TRUE(PixelsWhere(plain, IsGreen).empty());
  EXPECT_FALSE(PixelsWhere(arrow, IsGreen).empty());
  EXPECT_EQ(render("--time 0.1" + contacts).rgb, render("--time 0.1").rgb);

  // The arrow is what changed, and every changed pixel turned greener (its green over red rose:
  // the arrow, or its antialiased edge, over the orange ball or the grey floor).
  int x0 = arrow.width, x1 = -1, y0 = arrow.height, y1 = -1, changed = 0;
  double arrow_x = 0;
  for (int y = 0; y < arrow.height; ++y) {
    for (int x = 0; x < arrow.width; ++x) {
      const uint8_t *a = arrow.At(x, y), *p = plain.At(x, y);
      if (std::equal(a, a + 3, p)) continue;
      EXPECT_GT(a[1] - a[0], p[1] - p[0]) << x << ", " << y;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      arrow_x += x, ++changed;
    }
  }
  ASSERT_GT(changed, 40);  // an arrow some 25 pixels long and 2 wide
  arrow_x /= changed;
  // The ball in the plain picture: its centre column, its lowest row, its radius (pixels).
  const auto ball = PixelsWhere(plain, IsOrange);
  ASSERT_GT(ball.size(), 1000u);
  int top = plain.height, bottom = -1;
  double ball_x = 0;
  for (const auto& [x, y] : ball) top = std::min(top, y), bottom = std::max(bottom, y), ball_x += x;
  ball_x /= ball.size();
  const double radius = 0.5 * (bottom - top + 1);
  // The camera is framed on the ball, not on the floor's slab (a stand-in for an unbounded
  // half-space): the ball's bounding sphere (radius sqrt(3) r) fills the view with 5% margin,
  // so the ball spans 1 / (1.05 sqrt(3)) = 55% of the picture's height.
  EXPECT_GT(2.0 * radius, 0.5 * plain.height);
  EXPECT_NEAR(arrow_x, ball_x, 1.0);  // under the centre
  // Upright: no wider than its head, 0.14 of the weight's drawn length (one radius), plus a
  // pixel of antialiasing on each side.
  EXPECT_LE(x1 - x0, 0.14 * radius + 2.0);
  // From the contact point, nothing below it. The contact point is seen r (1 - cos 8.5 deg),
  // 1.1% of the radius, above the silhouette's lowest row, and perspective widens the
  // silhouette by 1 / cos(a) - 1 = 2.3% (the ball subtends a = 12 degrees from the camera):
  // 4% of the radius, plus 2 pixels of sampling.
  const double projection = 0.04 * radius;
  EXPECT_NEAR(y1, bottom, projection + 2.0);
  // Up to the centre: the head's tip narrower than the 0.5-pixel sample spacing (its first 1.4
  // pixels) may cover no sample, and each row found is within a pixel.
  EXPECT_NEAR(y0, bottom - 0.99 * radius, projection + 3.0);
}

// The camera frames the arrows with the model: the ball dropped 3 cm onto its floor with SMC
// contact lands with a peak force of about 20 weights, and its arrow (the weight drawn one
// radius long) reaches far above the ball. It stays in the picture, whole: no green pixel on
// the picture's edge, and its drawn length in pixels, against the ball's radius in the same
// picture, is the force over the weight (seen from 8.5 degrees above: cos 8.5 deg; the arrow
// spans the view, so perspective scales its ends and the ball differently: within 10%).
TEST_F(ExportContactsTest, RenderKeepsALongArrowInThePicture) {
  const std::string model = BallWithFloorAt(0.17);
  const CliRun run = Run("simulate " + model +
                         " --collision --contact smc --duration 0.2 --report-interval 1e-4 "
                         "--quiet --out " +
                         Path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The row of the largest upward force on the ball.
  const io::Storage contacts = io::ReadStorage(Path("out/contacts.sto"));
  int column = -1;
  for (size_t c = 0; c < contacts.labels.size(); ++c) {
    const std::string& label = contacts.labels[c];
    if (label.ends_with(".ball.force.Y")) column = static_cast<int>(c);
  }
  ASSERT_GE(column, 0);
  size_t landing = 0;
  const size_t width = contacts.labels.size();
  for (size_t r = 0; r < contacts.time.size(); ++r) {
    if (contacts.values[r * width + column] > contacts.values[landing * width + column])
      landing = r;
  }
  const double ratio = contacts.values[landing * width + column] / kWeight;
  ASSERT_GT(ratio, 10.0);  // an arrow ten radii long or more would have left the old picture
  std::ostringstream time;
  time.precision(17);
  time << contacts.time[landing];
  const std::string png = Path("landing.png");
  const CliRun r = Run("render " + model + " --states " + Path("out/states.sto") +
                       " --vis primitives --view front --width 800 --height 800 --time " +
                       time.str() + " --contacts " + Path("out/contacts.sto") + " --out " + png);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const viz::Image image = viz::DecodePng(viz::ReadFileBytes(png), png);
  const auto green = PixelsWhere(image, IsGreen);
  const auto ball = PixelsWhere(image, IsOrange);
  ASSERT_GT(green.size(), 20u);
  ASSERT_GT(ball.size(), 20u);
  int top = image.height, bottom = -1, ball_top = image.height, ball_bottom = -1;
  for (const auto& [x, y] : green) {
    EXPECT_TRUE(x > 0 && y > 0 && x < image.width - 1 && y < image.height - 1) << x << ", " << y;
    top = std::min(top, y), bottom = std::max(bottom, y);
  }
  for (const auto& [x, y] : ball)
    ball_top = std::min(ball_top, y), ball_bottom = std::max(ball_bottom, y);
  const double radius = 0.5 * (ball_bottom - ball_top + 1);
  const double drawn = bottom - top + 1;
  std::cout << "landing at " << time.str() << " s: force " << ratio << " weights; arrow " << drawn
            << " px, ball radius " << radius << " px\n";
  EXPECT_NEAR(drawn / (radius * std::cos(8.5 * M_PI / 180)), ratio, 0.1 * ratio);
}

// --ground-plane gives the floor when collision adds one.
TEST_F(ExportContactsTest, GroundPlaneOptionIsTheFloor) {
  const ParsedGlb glb =
      SimulateAndExport(kBall, "--collision --ground-plane -0.05 --duration 0.01");
  ASSERT_FALSE(HasFailure());
  const nlohmann::json& floor = glb.doc["scenes"][0]["extras"]["floor"];
  EXPECT_EQ(floor["point"][1], -0.05);
  EXPECT_EQ(floor["source"], "--ground-plane");
}

// SmoothSphereHalfSpaceForce names its column groups "Sphere" and "HalfSpace": the export finds
// the sphere's body through the force's socket, as the simulation knows it.
TEST_F(ExportContactsTest, SmoothForceGroupsAreFoundThroughTheSockets) {
  const CliRun run = Run("simulate " + kSmoothBall + " --duration 0.05 --quiet --out " +
                         Path("out") + " --export " + Path("sim.glb"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CliRun again = Run("export " + kSmoothBall + " --states " + Path("out/states.sto") +
                           " --contacts " + Path("out/contacts.sto") + " -o " + Path("exp.glb"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.err.find("names no body"), std::string::npos) << again.err;
  for (const char* name : {"sim.glb", "exp.glb"}) {
    const ParsedGlb glb = ReadGlb(name);
    const nlohmann::json& arrows = glb.doc["scenes"][0]["extras"]["contact_arrows"];
    ASSERT_EQ(arrows["arrows"].size(), 1u) << name;
    EXPECT_TRUE(arrows["arrows"][0]["name"].get<std::string>().ends_with(".Sphere")) << name;
    EXPECT_EQ(arrows["arrows"][0]["body"], 1) << name;
  }
}

TEST_F(ExportContactsTest, ContactsNeedAMotion) {
  std::ofstream(Path("contacts.sto")) << "Contacts\nendheader\ntime\n";
  for (const std::string out : {"x.glb", "x.png"}) {
    const std::string command = out.ends_with(".png") ? "render " : "export ";
    const CliRun run =
        Run(command + kBall + " --contacts " + Path("contacts.sto") + " -o " + Path(out));
    EXPECT_NE(run.exit_code, 0) << command;
    EXPECT_NE(run.err.find("--contacts needs --motion or --states"), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace sinew
