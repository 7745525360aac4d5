// XML-RPC values of the parameter server -> parameter tree, with no master.
#include <ctime>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/ros/xmlrpc_parameters.h"
#include "support/xmlrpc_list.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

using PV = ParameterValue;
using XmlRpc::XmlRpcValue;

PV convert(const XmlRpcValue& value, const std::string& name = "~") {
  PV tree = PV::makeString("marker");
  const Status status = fromXmlRpc(value, name, &tree);
  EXPECT_TRUE(status.ok) << status.message;
  return tree;
}

/// Converts expecting a refusal that leaves the tree alone; returns the message.
std::string refused(const XmlRpcValue& value, const std::string& name) {
  PV tree = PV::makeString("marker");
  const Status status = fromXmlRpc(value, name, &tree);
  EXPECT_FALSE(status.ok);
  EXPECT_EQ(tree, PV::makeString("marker"));
  return status.message;
}

TEST(FromXmlRpc, Scalars) {
  EXPECT_EQ(convert(XmlRpcValue(true)), PV::makeBool(true));
  EXPECT_EQ(convert(XmlRpcValue(false)), PV::makeBool(false));
  EXPECT_EQ(convert(XmlRpcValue(-12)), PV::makeInt(-12));
  EXPECT_EQ(convert(XmlRpcValue(10.0)), PV::makeDouble(10.0));  // stays a double
  EXPECT_EQ(convert(XmlRpcValue(0.25)), PV::makeDouble(0.25));
  EXPECT_EQ(convert(XmlRpcValue(std::string("10"))), PV::makeString("10"));  // not a number
  EXPECT_EQ(convert(XmlRpcValue("")), PV::makeString(""));
}

TEST(FromXmlRpc, ArraysKeepOrderAndItemTypes) {
  EXPECT_EQ(
      convert(test::xmlRpcList({1, 2.5, "x", true})),
      PV::makeList({PV::makeInt(1), PV::makeDouble(2.5), PV::makeString("x"), PV::makeBool(true)}));
  XmlRpcValue empty;
  empty.setSize(0);
  EXPECT_EQ(convert(empty), PV::makeList({}));
}

TEST(FromXmlRpc, NestedStructsAndArrays) {
  XmlRpcValue params;
  params["time_step"] = 0.001;
  params["table"]["size"] = test::xmlRpcList({1.2, 0.8});
  params["table"]["thickness"] = 0.03;
  params["scene_dirs"] = test::xmlRpcList({"a", "b"});
  params["bricks"] = test::xmlRpcList({XmlRpcValue(), XmlRpcValue()});
  params["bricks"][0]["id"] = "first";
  params["bricks"][1]["id"] = "second";
  params["bricks"][1]["position"] = test::xmlRpcList({0, 0, 0.1});

  PV expected;
  expected.set("time_step", PV::makeDouble(0.001));
  expected.setPath("table/size", PV::makeList({PV::makeDouble(1.2), PV::makeDouble(0.8)}));
  expected.setPath("table/thickness", PV::makeDouble(0.03));
  expected.set("scene_dirs", PV::makeList({PV::makeString("a"), PV::makeString("b")}));
  PV first;
  first.set("id", PV::makeString("first"));
  PV second;
  second.set("id", PV::makeString("second"));
  second.set("position", PV::makeList({PV::makeInt(0), PV::makeInt(0), PV::makeDouble(0.1)}));
  expected.set("bricks", PV::makeList({first, second}));

  const PV tree = convert(params);
  EXPECT_EQ(tree, expected);

  // The tree reads like one from yaml: an unknown parameter is found.
  params["table"]["thicknes"] = 0.05;
  const PV with_typo = convert(params);
  OptionsReader reader(with_typo);
  reader.section("table", [](OptionsReader& table) {
    Eigen::Vector2d size;
    double thickness = 0;
    table.read("size", &size);
    table.read("thickness", &thickness);
    return table.finish();
  });
  reader.skip("time_step");
  reader.skip("scene_dirs");
  reader.skip("bricks");
  EXPECT_EQ(reader.finish().message,
            "table/thicknes is not a known parameter (did you mean table/thickness? known here: "
            "size, thickness)");
}

TEST(FromXmlRpc, EmptyStructIsAnEmptyMap) {
  XmlRpcValue empty;
  empty.begin();  // makes it a struct (XmlRpcValue's way)
  ASSERT_EQ(empty.getType(), XmlRpcValue::TypeStruct);
  EXPECT_EQ(convert(empty), PV::makeMap());
}

TEST(FromXmlRpc, UnsupportedTypesAreNamed) {
  std::tm time{};
  time.tm_year = 120;
  time.tm_mday = 1;
  EXPECT_EQ(refused(XmlRpcValue(&time), "~stamp"),
            "parameter ~stamp has an unsupported type (date-time)");
  char bytes[] = "abc";
  EXPECT_EQ(refused(XmlRpcValue(bytes, 3), "~blob"),
            "parameter ~blob has an unsupported type (base64)");
  EXPECT_EQ(refused(XmlRpcValue(), "~nothing"),
            "parameter ~nothing has an unsupported type (invalid)");
}

TEST(FromXmlRpc, UnsupportedTypeDeepInsideIsNamedWithItsPath) {
  std::tm time{};
  XmlRpcValue params;
  params["a"] = 1;
  params["table"]["stamps"] = test::xmlRpcList({1, XmlRpcValue(&time)});
  EXPECT_EQ(refused(params, "~"), "parameter ~table/stamps[1] has an unsupported type (date-time)");
  XmlRpcValue below;
  below["x"]["y"] = XmlRpcValue();
  EXPECT_EQ(refused(below, "/stack_sim"),
            "parameter /stack_sim/x/y has an unsupported type (invalid)");
}

TEST(FromXmlRpc, DeepNestingIsRefused) {
  XmlRpcValue deep = 1;
  for (int i = 0; i < 150; ++i) {
    XmlRpcValue outer;
    outer["d"] = deep;
    deep = outer;
  }
  EXPECT_NE(refused(deep, "~").find("is nested more than 100 levels deep"), std::string::npos);
}

/// A map {key: value}, as the node's private namespace would hold it.
PV withMember(const std::string& key, PV value) {
  PV map = PV::makeMap();
  map.set(key, std::move(value));
  return map;
}

TEST(ListFromString, ARosrunListStringIsReadAsTheList) {
  // `rosrun ... _scene_dirs:=[/a, /b]` stores the text "[/a, /b]".
  PV parameters = withMember("scene_dirs", PV::makeString("[/a, /b]"));
  std::string note;
  const Status status = listFromString("scene_dirs", &parameters, &note);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(*parameters.find("scene_dirs"),
            PV::makeList({PV::makeString("/a"), PV::makeString("/b")}));
  EXPECT_NE(note.find("read as the list ['/a', '/b']"), std::string::npos) << note;
  // The core's reader now takes it as any list of strings.
  std::vector<std::string> dirs;
  OptionsReader reader(parameters);
  reader.read("scene_dirs", &dirs);
  EXPECT_EQ(dirs, (std::vector<std::string>{"/a", "/b"}));
}

TEST(ListFromString, AnyOtherStringIsAListOfOne) {
  PV parameters = withMember("scene_dirs", PV::makeString("/my scenes"));
  ASSERT_TRUE(listFromString("scene_dirs", &parameters).ok);
  EXPECT_EQ(*parameters.find("scene_dirs"), PV::makeList({PV::makeString("/my scenes")}));
}

TEST(ListFromString, AListOrAnAbsentKeyIsLeftAlone) {
  const PV list = withMember("scene_dirs", PV::makeList({PV::makeString("/a")}));
  PV parameters = list;
  std::string note;
  ASSERT_TRUE(listFromString("scene_dirs", &parameters, &note).ok);
  EXPECT_EQ(parameters, list);
  EXPECT_TRUE(note.empty());
  PV other = withMember("scene", PV::makeString("[x]"));
  ASSERT_TRUE(listFromString("scene_dirs", &other).ok);
  EXPECT_EQ(*other.find("scene"), PV::makeString("[x]"));
}

TEST(ListFromString, ABracketThatIsNoListOfStringsIsRefusedSayingHowToSetIt) {
  PV parameters = withMember("scene_dirs", PV::makeString("[[a], b"));
  const Status status = listFromString("scene_dirs", &parameters);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("~scene_dirs"), std::string::npos) << status.message;
  EXPECT_NE(status.message.find("rosparam set"), std::string::npos) << status.message;
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
