// ListNotSimulated: one line per element the engine does not handle yet, in model order.
#include <gtest/gtest.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/support.h>

namespace sinew {
namespace {

TEST(Support, ListsEverythingNotSimulatedYet) {
  // Ideal actuators, PrescribedControllers and WrapSphere (as WrapCylinder, WrapEllipsoid,
  // WrapTorus, WrapSphereObst, WrapCylinderObst and WrapDoubleCylinderObst) are simulated;
  // Millard2012AccelerationMuscle, other controllers, this constraint, contact geometry, a
  // plugin's wrap object and unknown joints are not yet.
  const std::string text = R"(<OpenSimDocument Version="40000"><Model name="m">
<Ground name="ground"/>
<BodySet><objects><Body name="b"><mass>1</mass>
  <WrapObjectSet><objects><WrapSphere name="ws"><radius>0.1</radius></WrapSphere>
    <WrapSphereObst name="wso"/><WrapCylinderObst name="wco"/>
    <WrapDoubleCylinderObst name="wd"><wrapVcylHomeBodyName>c</wrapVcylHomeBodyName>
    </WrapDoubleCylinderObst><MyPluginWrapObject name="wt"/></objects></WrapObjectSet>
</Body><Body name="c"><mass>1</mass></Body></objects></BodySet>
<JointSet><objects>
  <SliderJoint name="s"><socket_parent_frame>/ground</socket_parent_frame>
    <socket_child_frame>/bodyset/b</socket_child_frame><coordinates><Coordinate name="x"/></coordinates></SliderJoint>
  <MyPluginJoint name="plugin"><socket_parent_frame>/bodyset/b</socket_parent_frame>
    <socket_child_frame>/bodyset/c</socket_child_frame></MyPluginJoint>
</objects></JointSet>
<ForceSet><objects><CoordinateActuator name="act"><coordinate>x</coordinate></CoordinateActuator>
  <Millard2012AccelerationMuscle name="musc"/></objects></ForceSet>
<ConstraintSet><objects><RollingOnSurfaceConstraint name="roll"/></objects></ConstraintSet>
<ContactGeometrySet><objects><ContactSphere name="cs"><socket_frame>/bodyset/c</socket_frame>
  <radius>0.2</radius></ContactSphere></objects></ContactGeometrySet>
<ControllerSet><objects><PrescribedController name="ctl"/><ToyReflexController name="reflex"/>
</objects></ControllerSet>
<ProbeSet><objects><JointInternalPowerProbe name="probe"/></objects></ProbeSet>
</Model></OpenSimDocument>)";
  const model::ModelSpec spec = io::ReadOsimString(text, "support.osim");
  // The plugin joint is read, with its frames resolved.
  const model::JointSpec& plugin = spec.joints[spec.FindJoint("plugin")];
  EXPECT_EQ(plugin.kind, model::JointType::kUnknown);
  EXPECT_EQ(plugin.parent_body, spec.FindBody("b"));
  EXPECT_EQ(plugin.child_body, spec.FindBody("c"));
  const std::vector<std::string> expected = {
      "/jointset/plugin: MyPluginJoint",
      "/forceset/musc: Millard2012AccelerationMuscle",
      "/constraintset/roll: RollingOnSurfaceConstraint",
      "/controllerset/reflex: ToyReflexController",
      "/contactgeometryset/cs: ContactSphere",
      "/bodyset/b/wrapobjectset/wt: MyPluginWrapObject",
      "/probe: JointInternalPowerProbe",
  };
  EXPECT_EQ(opensim::ListNotSimulated(spec), expected);
}

}  // namespace
}  // namespace sinew
