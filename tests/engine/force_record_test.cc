// What force elements report (ForceElement::RecordLabels / CalcRecordValues and the
// ForceReporter that gathers them), against hand computations: the default record is the load
// AddLoads applies, and a run through Simulate reports the inputs the controller sets.
#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/controller.h>
#include <sinew/engine/force_reporter.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/loads.h>
#include <sinew/engine/simulation.h>
#include <sinew/engine/system.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/test_models.h"

namespace sinew::engine {
namespace {

using testing::Coord;
using testing::MakeBody;

// Pushes point (0, 1, 0) of body 1 with (1, 2, 3) N (in G) and coordinate 0 with 5 N; reports
// through the default record, over its support or (without one) over everything.
class Probe final : public ForceElement {
 public:
  Probe(std::string name, bool with_support) : name_(std::move(name)), support_(with_support) {}
  std::string name() const override { return name_; }
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddForceAtPoint(context.state, 1, Vec3(0, 1, 0), Vec3(1, 2, 3));
    loads.AddGeneralizedForce(0, 5.0);
  }
  std::optional<ForceSupport> Support() const override {
    if (!support_) return std::nullopt;
    return ForceSupport{{1}, {0}};
  }

 private:
  std::string name_;
  bool support_;
};

// A generalized force equal to the element's input, on coordinate 0 (one coordinate of support).
class InputForce final : public ForceElement {
 public:
  std::string name() const override { return "push"; }
  std::vector<std::string> InputNames() const override { return {"level"}; }
  void AddLoads(const ForceContext& context, Loads& loads) const override {
    loads.AddGeneralizedForce(0, context.input(0));
  }
  std::optional<ForceSupport> Support() const override { return ForceSupport{{}, {0}}; }
};

// Sets every input to 2 + t.
class LinearController final : public Controller {
 public:
  void CalcInputs(const System&, const State& state, Eigen::Ref<VecX> inputs) const override {
    inputs.setConstant(2.0 + state.t);
  }
};

// Two blocks on sliders along x: "block" (coordinate x) and "cart" (coordinate c).
System MakeTwoSliders() {
  System system(Vec3(0, -9.80665, 0));
  const int block = system.AddBody(MakeBody("block", 1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  const int cart = system.AddBody(MakeBody("cart", 2.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  system.AddJoint("slide", 0, Transform(), block, Transform(), JointForm::kParameterized,
                  std::make_shared<testing::SliderModel>(), {Coord("x")});
  system.AddJoint("roll", 0, Transform(), cart, Transform(), JointForm::kParameterized,
                  std::make_shared<testing::SliderModel>(), {Coord("c")});
  return system;
}

TEST(ForceRecordTest, DefaultRecordIsTheLoadAddLoadsAppliesOnTheSupport) {
  System system = MakeTwoSliders();
  system.AddForceElement(std::make_shared<Probe>("probe", true));
  system.AddForceElement(std::make_shared<Probe>("wide", false));
  system.Finalize();
  const ForceReporter reporter(system);
  const std::vector<std::string> probe = {"probe.block.force.X",
                                          "probe.block.force.Y",
                                          "probe.block.force.Z",
                                          "probe.block.torque.X",
                                          "probe.block.torque.Y",
                                          "probe.block.torque.Z",
                                          "probe.x"};
  // Without a support: every body but ground, then every coordinate.
  std::vector<std::string> expected = probe;
  for (const char* body : {"block", "cart"}) {
    for (const char* kind : {".force.", ".torque."}) {
      for (const char* axis : {"X", "Y", "Z"}) {
        expected.push_back(std::string("wide.") + body + kind + axis);
      }
    }
  }
  expected.push_back("wide.x");
  expected.push_back("wide.c");
  EXPECT_EQ(reporter.labels(), expected);

  // At the default pose the block's frame is ground's: the torque about Bo is
  // (0, 1, 0) x (1, 2, 3) = (1*3 - 0*2, 0*1 - 0*3, 0*2 - 1*1) = (3, 0, -1).
  const State state = MakeDefaultState(system);
  std::vector<double> row;
  reporter.CalcRow(state, row);
  const std::vector<double> on_block = {1, 2, 3, 3, 0, -1};
  std::vector<double> hand = on_block;
  hand.push_back(5.0);
  hand.insert(hand.end(), on_block.begin(), on_block.end());
  hand.insert(hand.end(), {0, 0, 0, 0, 0, 0, 5.0, 0.0});
  ASSERT_EQ(row.size(), hand.size());
  for (size_t i = 0; i < row.size(); ++i) EXPECT_DOUBLE_EQ(row[i], hand[i]) << expected[i];
}

TEST(ForceRecordTest, AForceOnOneCoordinateIsOneColumnNamedAfterIt) {
  System system = MakeTwoSliders();
  system.AddForceElement(std::make_shared<InputForce>());
  system.Finalize();
  EXPECT_EQ(ForceReporter(system).labels(), std::vector<std::string>{"push"});
}

TEST(ForceRecordTest, SimulateReportsTheInputsItsControllerSetsFromTheFirstRow) {
  // The first row is reported before any step: it must hold the controller's inputs (2 + t),
  // not the state's defaults (0), as every later row does.
  System system = MakeTwoSliders();
  system.AddForceElement(std::make_shared<InputForce>());
  system.Finalize();
  auto integrator = MakeIntegrator("rk45", system, {});
  integrator->SetController(std::make_shared<LinearController>());
  State state = MakeDefaultState(system);
  const ForceReporter reporter(system);
  std::vector<double> row;
  std::vector<std::pair<double, double>> rows;
  SimulationOptions options;
  options.duration = 0.2;
  options.report_interval = 0.1;
  Simulate(*integrator, state, options, [&](const State& s) {
    reporter.CalcRow(s, row);
    rows.emplace_back(s.t, row.at(0));
  });
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& [t, push] : rows) EXPECT_NEAR(push, 2.0 + t, 1e-15) << t;
}

// Reports one label but two values.
class Miscounted final : public ForceElement {
 public:
  std::string name() const override { return "bad"; }
  void AddLoads(const ForceContext&, Loads&) const override {}
  std::vector<std::string> RecordLabels(const System&) const override { return {"bad"}; }
  void CalcRecordValues(const ForceContext&, std::vector<double>& values) const override {
    values.insert(values.end(), {1.0, 2.0});
  }
};

TEST(ForceRecordTest, AnElementWhoseValuesDoNotMatchItsLabelsIsAnError) {
  System system = MakeTwoSliders();
  system.AddForceElement(std::make_shared<Miscounted>());
  system.Finalize();
  std::vector<double> row;
  try {
    ForceReporter(system).CalcRow(MakeDefaultState(system), row);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'bad' reported 2 values for 1 labels"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace sinew::engine
