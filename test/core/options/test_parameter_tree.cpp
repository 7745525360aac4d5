// The parameter tree, the options reader and the yaml front end, without ROS.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/options/yaml_parameters.h"

namespace brick_stack_sim {
namespace {

using PV = ParameterValue;

PV numbers(std::initializer_list<double> values) {
  PV::List items;
  for (double value : values) items.push_back(PV::makeDouble(value));
  return PV::makeList(std::move(items));
}

/// Parses `text`, failing the test on an error.
PV yaml(const std::string& text) {
  PV tree;
  const Status status = parseYamlParameters(text, "test.yaml", &tree);
  EXPECT_TRUE(status.ok) << status.message;
  return tree;
}

/// Parses `text` expecting a refusal; returns the message.
std::string yamlError(const std::string& text) {
  PV tree = PV::makeInt(42);  // a marker: a refusal must leave it alone
  const Status status = parseYamlParameters(text, "test.yaml", &tree);
  EXPECT_FALSE(status.ok) << "accepted: " << text;
  EXPECT_EQ(tree, PV::makeInt(42)) << "tree changed by a refused parse";
  return status.message;
}

/// The value at slash-separated `path` of `tree`; the string "<absent>" when there is none, so that
/// a test fails instead of crashing.
PV at(const PV& tree, const std::string& path) {
  const PV* node = &tree;
  std::size_t begin = 0;
  while (node != nullptr && begin <= path.size()) {
    std::size_t end = path.find('/', begin);
    if (end == std::string::npos) end = path.size();
    node = node->find(path.substr(begin, end - begin));
    begin = end + 1;
  }
  return node != nullptr ? *node : PV::makeString("<absent>");
}

std::vector<std::string> keysOf(const PV& map) {
  std::vector<std::string> keys;
  for (const auto& member : map.map()) keys.push_back(member.first);
  return keys;
}

// ---------------------------------------------------------------------------------------------
// ParameterValue

TEST(ParameterValue, DefaultIsAnEmptyMap) {
  const PV value;
  EXPECT_TRUE(value.isMap());
  EXPECT_EQ(value.type(), PV::Type::kMap);
  EXPECT_TRUE(value.map().empty());
  EXPECT_EQ(value.find("x"), nullptr);
  EXPECT_EQ(PV::makeMap(), value);
}

TEST(ParameterValue, TypesAndAccessors) {
  EXPECT_EQ(PV::makeBool(true).type(), PV::Type::kBool);
  EXPECT_TRUE(PV::makeBool(true).asBool());
  EXPECT_FALSE(PV::makeBool(true).isNumber());

  const PV integer = PV::makeInt(-3);
  EXPECT_EQ(integer.type(), PV::Type::kInt);
  EXPECT_TRUE(integer.isNumber());
  EXPECT_EQ(integer.asInt(), -3);
  EXPECT_EQ(integer.asDouble(), -3.0);

  const PV real = PV::makeDouble(0.25);
  EXPECT_EQ(real.type(), PV::Type::kDouble);
  EXPECT_TRUE(real.isNumber());
  EXPECT_FALSE(real.isInt());
  EXPECT_EQ(real.asDouble(), 0.25);

  EXPECT_EQ(PV::makeString("abc").asString(), "abc");
  EXPECT_FALSE(PV::makeString("3").isNumber());
  EXPECT_EQ(numbers({1, 2}).list().size(), 2u);
  EXPECT_EQ(numbers({1, 2}).type(), PV::Type::kList);
  EXPECT_NE(PV::makeInt(1), PV::makeDouble(1.0));  // same number, different types
}

TEST(ParameterValue, SetKeepsKeysSortedUniqueAndReplaces) {
  PV map;
  map.set("b", PV::makeInt(2));
  map.set("c", PV::makeInt(3));
  map.set("a", PV::makeInt(1));
  map.set("b", PV::makeString("two"));
  EXPECT_EQ(keysOf(map), (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_NE(map.find("b"), nullptr);
  EXPECT_EQ(at(map, "b"), PV::makeString("two"));
  EXPECT_EQ(map.find("d"), nullptr);
  EXPECT_EQ(PV::makeInt(3).find("a"), nullptr);  // not a map: nothing to find
}

TEST(ParameterValue, SetPathCreatesMapsAndReplacesNonMapsOnTheWay) {
  PV tree;
  tree.setPath("table/size", numbers({1.2, 0.8}));
  tree.setPath("table/thickness", PV::makeDouble(0.03));
  tree.setPath("gravity", PV::makeDouble(9.81));
  ASSERT_NE(tree.find("table"), nullptr);
  EXPECT_EQ(keysOf(at(tree, "table")), (std::vector<std::string>{"size", "thickness"}));
  EXPECT_EQ(at(tree, "table/size"), numbers({1.2, 0.8}));

  tree.setPath("gravity/x", PV::makeInt(1));  // a double on the way becomes a map
  EXPECT_TRUE(at(tree, "gravity").isMap());
  EXPECT_EQ(at(tree, "gravity/x"), PV::makeInt(1));

  tree.setPath("/a//b/", PV::makeBool(true));  // empty components are skipped
  ASSERT_NE(tree.find("a"), nullptr);
  EXPECT_EQ(at(tree, "a/b"), PV::makeBool(true));

  tree.setPath("", PV::makeInt(7));  // no component: the whole value
  EXPECT_EQ(tree, PV::makeInt(7));
}

TEST(ParameterValue, MergeMergesMapsRecursivelyAndReplacesEverythingElse) {
  PV base = yaml(
      "time_step: 0.001\n"
      "table: {size: [1.2, 0.8], thickness: 0.03}\n"
      "list: [1, 2, 3]\n"
      "scalar_then_map: 3\n"
      "map_then_scalar: {a: 1}\n");
  const PV later = yaml(
      "table: {thickness: 0.05, height: 0.7}\n"
      "list: [9]\n"
      "scalar_then_map: {b: 2}\n"
      "map_then_scalar: 4\n"
      "new_key: x\n");
  base.merge(later);
  const PV expected = yaml(
      "time_step: 0.001\n"
      "table: {size: [1.2, 0.8], thickness: 0.05, height: 0.7}\n"
      "list: [9]\n"
      "scalar_then_map: {b: 2}\n"
      "map_then_scalar: 4\n"
      "new_key: x\n");
  EXPECT_EQ(base, expected);

  PV scalar = PV::makeInt(1);
  scalar.merge(base);  // a non-map is replaced by a map
  EXPECT_EQ(scalar, base);
  base.merge(PV::makeString("all gone"));  // and a map by a non-map
  EXPECT_EQ(base, PV::makeString("all gone"));
}

TEST(ParameterValue, MergeOfOwnSubtreeIsSafe) {
  PV tree = yaml("a: {x: 1, y: 2}\nb: {x: 5}\nx: 0\n");
  ASSERT_NE(tree.find("a"), nullptr);
  tree.merge(*tree.find("a"));  // `other` lives inside the tree being changed
  EXPECT_EQ(tree, yaml("a: {x: 1, y: 2}\nb: {x: 5}\nx: 1\ny: 2\n"));
  PV copy = tree;
  tree.merge(tree);
  EXPECT_EQ(tree, copy);
}

TEST(ParameterValue, Describe) {
  EXPECT_EQ(PV::makeBool(true).describe(), "bool true");
  EXPECT_EQ(PV::makeBool(false).describe(), "bool false");
  EXPECT_EQ(PV::makeInt(3).describe(), "int 3");
  EXPECT_EQ(PV::makeDouble(0.5).describe(), "double 0.5");
  EXPECT_EQ(PV::makeDouble(3.0).describe(), "double 3");
  EXPECT_EQ(PV::makeDouble(0.1).describe(), "double 0.1");  // shortest, not 0.1000000000000000055
  EXPECT_EQ(PV::makeDouble(-std::numeric_limits<double>::infinity()).describe(), "double -inf");
  EXPECT_EQ(PV::makeString("abc").describe(), "string 'abc'");
  EXPECT_EQ(numbers({1, 2, 3}).describe(), "a list of 3");
  EXPECT_EQ(PV::makeMap().describe(), "a map");
}

TEST(ParameterValue, DescribeCutsLongStrings) {
  EXPECT_EQ(PV::makeString(std::string(60, 'a')).describe(),
            "string '" + std::string(60, 'a') + "'");
  const std::string described = PV::makeString(std::string(10000, 'a')).describe();
  EXPECT_EQ(described, "string '" + std::string(60, 'a') + "...' (10000 characters)");
  EXPECT_EQ(PV::makeString("two\nlines").describe(), "string 'two\\nlines'");
}

TEST(ParameterValue, ShortenForMessageEscapesAndDoesNotSplitUtf8) {
  EXPECT_EQ(shortenForMessage("a\tb\x01"), "a\\tb\\x01");
  EXPECT_EQ(shortenForMessage("abcdef", 3), "abc...");
  // "x" then 2-byte characters: byte 4 is the middle of the second "é", so the cut backs up to 3.
  const std::string accented = "x\xc3\xa9\xc3\xa9\xc3\xa9";
  EXPECT_EQ(shortenForMessage(accented, 4), "x\xc3\xa9...");
  EXPECT_EQ(shortenForMessage(accented, 5), "x\xc3\xa9\xc3\xa9...");
}

// ---------------------------------------------------------------------------------------------
// OptionsReader

struct Everything {
  double real = 1.5;
  int integer = 4;
  bool flag = false;
  std::string text = "default";
  std::vector<double> reals{1.0};
  std::vector<std::string> texts{"d"};
  Eigen::Vector2d pair{1.0, 2.0};
  Eigen::Vector3d triple{1.0, 2.0, 3.0};
};

/// Every field of `e` still holds its default.
void expectDefaults(const Everything& e) {
  const Everything defaults;
  EXPECT_EQ(e.real, defaults.real);
  EXPECT_EQ(e.integer, defaults.integer);
  EXPECT_EQ(e.flag, defaults.flag);
  EXPECT_EQ(e.text, defaults.text);
  EXPECT_EQ(e.reals, defaults.reals);
  EXPECT_EQ(e.texts, defaults.texts);
  EXPECT_EQ(e.pair, defaults.pair);
  EXPECT_EQ(e.triple, defaults.triple);
}

void readEverything(OptionsReader& reader, Everything* e) {
  reader.read("real", &e->real);
  reader.read("integer", &e->integer);
  reader.read("flag", &e->flag);
  reader.read("text", &e->text);
  reader.read("reals", &e->reals);
  reader.read("texts", &e->texts);
  reader.read("pair", &e->pair);
  reader.read("triple", &e->triple);
}

TEST(OptionsReader, ReadsEveryTypeWhenPresent) {
  const PV tree = yaml(
      "real: 0.25\ninteger: -7\nflag: true\ntext: hello\nreals: [1, 2.5, -3]\n"
      "texts: [a, 'b']\npair: [0.5, 6]\ntriple: [7, 8, 9.5]\n");
  OptionsReader reader(tree);
  Everything e;
  readEverything(reader, &e);
  const Status status = reader.finish();
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_TRUE(reader.ok());
  EXPECT_EQ(e.real, 0.25);
  EXPECT_EQ(e.integer, -7);
  EXPECT_TRUE(e.flag);
  EXPECT_EQ(e.text, "hello");
  EXPECT_EQ(e.reals, (std::vector<double>{1.0, 2.5, -3.0}));
  EXPECT_EQ(e.texts, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(e.pair, Eigen::Vector2d(0.5, 6.0));
  EXPECT_EQ(e.triple, Eigen::Vector3d(7.0, 8.0, 9.5));
}

TEST(OptionsReader, AbsentKeysKeepTheDefaults) {
  const PV tree;
  OptionsReader reader(tree);
  Everything e;
  readEverything(reader, &e);
  EXPECT_TRUE(reader.finish().ok);
  expectDefaults(e);
}

TEST(OptionsReader, EmptyListsAreRead) {
  const PV tree = yaml("reals: []\ntexts: []\n");
  OptionsReader reader(tree);
  Everything e;
  reader.read("reals", &e.reals);
  reader.read("texts", &e.texts);
  ASSERT_TRUE(reader.finish().ok);
  EXPECT_TRUE(e.reals.empty());
  EXPECT_TRUE(e.texts.empty());
}

/// Reads `key` of `tree` into a default Everything expecting a refusal with exactly `message`,
/// and checks that nothing changed.
void expectRefused(const std::string& text, const std::string& message) {
  const PV tree = yaml(text);
  OptionsReader reader(tree);
  Everything e;
  readEverything(reader, &e);
  EXPECT_FALSE(reader.ok()) << text;
  EXPECT_EQ(reader.finish().message, message) << text;
  expectDefaults(e);
}

TEST(OptionsReader, WrongTypesAreNamedWithTheValueFound) {
  expectRefused("real: fast", "real is string 'fast', expected a number");
  expectRefused("real: [1]", "real is a list of 1, expected a number");
  expectRefused("real: true", "real is bool true, expected a number");
  expectRefused("integer: '3'", "integer is string '3', expected an integer");
  expectRefused("flag: 'true'", "flag is string 'true', expected a bool");
  expectRefused("flag: 1", "flag is int 1, expected a bool");
  expectRefused("text: 3", "text is int 3, expected a string");
  expectRefused("text: {a: 1}", "text is a map, expected a string");
  expectRefused("reals: 3", "reals is int 3, expected a list of numbers");
  expectRefused("reals: [1, wide]", "reals[1] is string 'wide', expected a number");
  expectRefused("texts: a", "texts is string 'a', expected a list of strings");
  expectRefused("texts: [a, 3]", "texts[1] is int 3, expected a string");
}

TEST(OptionsReader, IntegerAcceptedForDouble) {
  const PV tree = yaml("real: 10");
  OptionsReader reader(tree);
  double real = 0.5;
  reader.read("real", &real);
  EXPECT_TRUE(reader.finish().ok);
  EXPECT_EQ(real, 10.0);
}

TEST(OptionsReader, DoubleRefusedForInt) {
  expectRefused("integer: 20.5", "integer is double 20.5, expected an integer");
  expectRefused("integer: 20.0", "integer is double 20, expected an integer");  // not truncated
}

TEST(OptionsReader, IntegerMustFitAnInt) {
  expectRefused("integer: 3000000000",
                "integer is int 3000000000, expected an integer from -2147483648 to 2147483647");
  expectRefused("integer: -2147483649",
                "integer is int -2147483649, expected an integer from -2147483648 to 2147483647");
  for (const long long edge : {static_cast<long long>(INT_MAX), static_cast<long long>(INT_MIN)}) {
    PV tree;
    tree.set("integer", PV::makeInt(edge));
    OptionsReader reader(tree);
    int integer = 0;
    reader.read("integer", &integer);
    EXPECT_TRUE(reader.finish().ok);
    EXPECT_EQ(integer, edge);
  }
}

TEST(OptionsReader, FixedSizeVectorsNeedExactlyThatManyNumbers) {
  expectRefused("pair: [1, 2, 3]", "pair is a list of 3, expected a list of 2 numbers");
  expectRefused("pair: [1]", "pair is a list of 1, expected a list of 2 numbers");
  expectRefused("pair: 3.0", "pair is double 3, expected a list of 2 numbers");
  expectRefused("pair: [1, wide]", "pair[1] is string 'wide', expected a number");
  expectRefused("triple: [1, 2]", "triple is a list of 2, expected a list of 3 numbers");
  expectRefused("triple: [1, 2, [3]]", "triple[2] is a list of 1, expected a number");
}

TEST(OptionsReader, FirstErrorWinsAndLaterCallsDoNothing) {
  const PV tree = yaml("a: x\nb: y\nc: 3.5\nunknown: 1\n");
  OptionsReader reader(tree);
  double a = 0, b = 0, c = 0;
  reader.read("a", &a);
  reader.read("b", &b);
  reader.read("c", &c);  // valid, but after an error: not read
  reader.fail(Status::error("later failure"));
  EXPECT_FALSE(reader.ok());
  EXPECT_EQ(reader.finish().message, "a is string 'x', expected a number");
  EXPECT_EQ(c, 0.0);
}

TEST(OptionsReader, FailRecordsTheFirstErrorAndIgnoresSuccess) {
  const PV tree;
  OptionsReader reader(tree, "table/");
  reader.fail(Status::success());
  EXPECT_TRUE(reader.ok());
  EXPECT_TRUE(reader.finish().ok);
  reader.fail(Status::error("first"));
  reader.fail(Status::error("second"));
  EXPECT_EQ(reader.finish().message, "first");
}

TEST(OptionsReader, NamedPutsThePathInFront) {
  const PV tree;
  const OptionsReader table(tree, "world/table/");
  EXPECT_EQ(table.named(Status::error("thickness = 0: must be > 0 m")).message,
            "world/table/thickness = 0: must be > 0 m");
  EXPECT_TRUE(table.named(Status::success()).ok);
  const OptionsReader root(tree);
  EXPECT_EQ(root.named(Status::error("gravity = -1: must be >= 0 m/s^2")).message,
            "gravity = -1: must be >= 0 m/s^2");
}

TEST(OptionsReader, UnknownKeyAtTheRootIsNamedWithTheKnownKeys) {
  const PV tree = yaml("time_stepp: 0.01\ngravity: 9.8\n");
  OptionsReader reader(tree);
  double time_step = 0.001, gravity = 9.81, fall_off_depth = 1.0;
  reader.read("time_step", &time_step);
  reader.read("gravity", &gravity);
  reader.read("fall_off_depth", &fall_off_depth);
  EXPECT_TRUE(reader.ok());  // unknown keys are found by finish() only
  EXPECT_EQ(reader.finish().message,
            "time_stepp is not a known parameter (did you mean time_step? known here: "
            "fall_off_depth, gravity, time_step)");
}

TEST(OptionsReader, FirstUnknownKeyInKeyOrderAndNoneKnown) {
  const PV tree = yaml("zz: 1\nbb: 2\n");
  const OptionsReader reader(tree);
  EXPECT_EQ(reader.finish().message, "bb is not a known parameter (known here: none)");
}

TEST(OptionsReader, SkipMakesAKeyKnown) {
  const PV tree = yaml("rviz_only: {anything: 1}\nrate: 3\n");
  OptionsReader reader(tree);
  double rate = 0;
  reader.read("rate", &rate);
  EXPECT_FALSE(reader.finish().ok);
  reader.skip("rviz_only");
  EXPECT_TRUE(reader.finish().ok) << reader.finish().message;
}

TEST(OptionsReader, KnownKeysListIsCut) {
  PV tree;
  tree.set("unknown", PV::makeInt(1));
  OptionsReader reader(tree);
  for (int i = 0; i < 30; ++i) {
    char name[16];
    std::snprintf(name, sizeof(name), "key_%02d", i);
    reader.skip(name);
  }
  const std::string message = reader.finish().message;
  EXPECT_NE(message.find("known here: key_00, key_01,"), std::string::npos) << message;
  EXPECT_NE(message.find("key_19, ...)"), std::string::npos) << message;
  EXPECT_EQ(message.find("key_20"), std::string::npos) << message;
}

TEST(OptionsReader, LongUnknownKeyIsCut) {
  PV tree;
  const std::string huge(10000, 'k');
  tree.set(huge, PV::makeInt(1));
  const OptionsReader reader(tree);
  const std::string message = reader.finish().message;
  EXPECT_EQ(message.find(huge), std::string::npos);
  EXPECT_LT(message.size(), 200u) << message;
  EXPECT_EQ(message.rfind(std::string(60, 'k') + "... is not a known parameter", 0), 0u) << message;
}

TEST(OptionsReader, ValuesNotAMap) {
  const PV list = numbers({1, 2});
  const OptionsReader root(list);
  EXPECT_FALSE(root.ok());
  EXPECT_EQ(root.finish().message, "the parameters are a list of 2, expected a map");
  const PV integer = PV::makeInt(3);
  OptionsReader table(integer, "world/table/");
  double thickness = 0.03;
  table.read("thickness", &thickness);
  EXPECT_EQ(table.finish().message, "world/table is int 3, expected a map");
  EXPECT_EQ(table.path(), "world/table/");
}

// A module in the style the project uses, and its parent.
struct TableOptions {
  Eigen::Vector2d size{1.2, 0.8};
  double thickness = 0.03;
};

struct SleepingOptions {
  bool enabled = true;
  double threshold = 0.005;
};

struct WorldOptions {
  double time_step = 0.001;
  TableOptions table;
  SleepingOptions sleeping;
};

int table_reads = 0;

Status readTableOptions(OptionsReader& reader, TableOptions* table) {
  ++table_reads;
  TableOptions t = *table;
  reader.read("size", &t.size);
  reader.read("thickness", &t.thickness);
  if (Status done = reader.finish(); !done) return done;
  if (!(t.thickness > 0.0)) {
    std::ostringstream message;
    message << "thickness = " << t.thickness << ": must be > 0 m";
    return reader.named(Status::error(message.str()));
  }
  *table = t;
  return Status::success();
}

/// Forgets finish(): the parent's section() must catch unknown keys anyway.
Status readSleepingCarelessly(OptionsReader& reader, SleepingOptions* sleeping) {
  reader.read("enabled", &sleeping->enabled);
  reader.read("threshold", &sleeping->threshold);
  return Status::success();
}

Status readWorld(const PV& tree, WorldOptions* world) {
  OptionsReader reader(tree);
  reader.read("time_step", &world->time_step);
  reader.section("table", &readTableOptions, &world->table);
  reader.section("sleeping", &readSleepingCarelessly, &world->sleeping);
  return reader.finish();
}

TEST(OptionsReader, SectionReadsANestedMap) {
  WorldOptions world;
  table_reads = 0;
  const Status status =
      readWorld(yaml("time_step: 0.002\ntable: {size: [2, 1], thickness: 0.05}\n"), &world);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(table_reads, 1);
  EXPECT_EQ(world.time_step, 0.002);
  EXPECT_EQ(world.table.size, Eigen::Vector2d(2, 1));
  EXPECT_EQ(world.table.thickness, 0.05);
  EXPECT_TRUE(world.sleeping.enabled);
}

TEST(OptionsReader, AbsentSectionIsNotCalled) {
  WorldOptions world;
  table_reads = 0;
  ASSERT_TRUE(readWorld(yaml("time_step: 0.002\n"), &world).ok);
  EXPECT_EQ(table_reads, 0);
  EXPECT_EQ(world.table.size, Eigen::Vector2d(1.2, 0.8));
}

TEST(OptionsReader, SectionThatIsNotAMap) {
  WorldOptions world;
  table_reads = 0;
  EXPECT_EQ(readWorld(yaml("sleeping: 3.0\n"), &world).message,
            "sleeping is double 3, expected a map");
  EXPECT_EQ(readWorld(yaml("table: [1, 2]\n"), &world).message,
            "table is a list of 2, expected a map");
  EXPECT_EQ(table_reads, 0);
}

TEST(OptionsReader, ErrorsInsideASectionCarryItsPath) {
  WorldOptions world;
  EXPECT_EQ(readWorld(yaml("table: {size: [1, wide]}\n"), &world).message,
            "table/size[1] is string 'wide', expected a number");
  EXPECT_EQ(readWorld(yaml("table: {sizee: [1, 2]}\n"), &world).message,
            "table/sizee is not a known parameter (did you mean table/size? known here: size, "
            "thickness)");
  EXPECT_EQ(readWorld(yaml("table: {thickness: 0}\n"), &world).message,
            "table/thickness = 0: must be > 0 m");
  // A section that forgets finish() still refuses an unknown key.
  EXPECT_EQ(readWorld(yaml("sleeping: {enabled: false, treshold: 1}\n"), &world).message,
            "sleeping/treshold is not a known parameter (did you mean sleeping/threshold? known "
            "here: enabled, threshold)");
  // An error leaves the section's options alone.
  EXPECT_EQ(world.table.size, Eigen::Vector2d(1.2, 0.8));
  EXPECT_EQ(world.table.thickness, 0.03);
}

TEST(OptionsReader, UnknownKeyAtTheRootAfterSections) {
  WorldOptions world;
  EXPECT_EQ(readWorld(yaml("time_stepp: 0.01\ntable: {thickness: 0.02}\n"), &world).message,
            "time_stepp is not a known parameter (did you mean time_step? known here: sleeping, "
            "table, time_step)");
}

TEST(OptionsReader, NestedSectionPathsAndCallables) {
  const PV tree = yaml("a: {b: {c: {x: 1, y: oops}}}\n");
  std::string seen_path;
  double x = 0, y = 0;
  OptionsReader reader(tree);
  reader.section("a", [&](OptionsReader& a) {
    a.section("b", [&](OptionsReader& b) {
      b.section("c", [&](OptionsReader& c) {
        seen_path = c.path();
        c.read("x", &x);
        c.read("y", &y);
        return c.finish();
      });
      return b.finish();
    });
    return a.finish();
  });
  EXPECT_EQ(seen_path, "a/b/c/");
  EXPECT_EQ(x, 1.0);
  EXPECT_EQ(reader.finish().message, "a/b/c/y is string 'oops', expected a number");

  const PV unknown = yaml("a: {b: {c: {x: 1, z: 2}}}\n");
  OptionsReader second(unknown);
  second.section("a", [&](OptionsReader& a) {
    a.section("b", [&](OptionsReader& b) {
      b.section("c", [&](OptionsReader& c) {
        c.read("x", &x);
        return Status::success();
      });
      return Status::success();
    });
    return Status::success();
  });
  EXPECT_EQ(second.finish().message,
            "a/b/c/z is not a known parameter (did you mean a/b/c/x? known here: x)");
}

TEST(OptionsReader, UserNamedKeysThroughValues) {
  // One section per brick type, named by the user: the module walks values().
  const PV tree = yaml("kapla: {mass: 0.004}\njenga: {mass: 0.02, colour: red}\n");
  OptionsReader reader(tree);
  std::vector<std::pair<std::string, double>> masses;
  for (const auto& member : reader.values().map()) {
    const std::string name = member.first;
    reader.section(name, [&](OptionsReader& type) {
      double mass = 0;
      type.read("mass", &mass);
      masses.emplace_back(name, mass);
      return type.finish();
    });
  }
  EXPECT_EQ(reader.finish().message, "jenga/colour is not a known parameter (known here: mass)");
  ASSERT_EQ(masses.size(), 1u);
  EXPECT_EQ(masses[0].first, "jenga");
}

// ---------------------------------------------------------------------------------------------
// YAML

TEST(YamlParameters, ScalarTypesAsRosparam) {
  const PV tree = yaml(
      "b1: true\nb2: False\nb3: YES\nb4: no\nb5: On\nb6: oFF\n"
      "i1: 10\ni2: -3\ni3: +7\ni4: 007\n"
      "d1: 1e-3\nd2: .5\nd3: 1.\nd4: -2.5E+2\nd5: 10.0\n"
      "big: 99999999999999999999\n"
      "s1: '10'\ns2: \"1e-3\"\ns3: 'true'\ns4: abc\ns5: 0x10\ns6: 1_000\ns7: inf\ns8: y\n"
      "s9: |\n  block\n");
  for (const char* key : {"b1", "b3", "b5"}) EXPECT_EQ(at(tree, key), PV::makeBool(true)) << key;
  for (const char* key : {"b2", "b4", "b6"}) EXPECT_EQ(at(tree, key), PV::makeBool(false)) << key;
  EXPECT_EQ(at(tree, "i1"), PV::makeInt(10));
  EXPECT_EQ(at(tree, "i2"), PV::makeInt(-3));
  EXPECT_EQ(at(tree, "i3"), PV::makeInt(7));
  EXPECT_EQ(at(tree, "i4"), PV::makeInt(7));
  EXPECT_EQ(at(tree, "d1"), PV::makeDouble(1e-3));
  EXPECT_EQ(at(tree, "d2"), PV::makeDouble(0.5));
  EXPECT_EQ(at(tree, "d3"), PV::makeDouble(1.0));
  EXPECT_EQ(at(tree, "d4"), PV::makeDouble(-250.0));
  EXPECT_EQ(at(tree, "d5"), PV::makeDouble(10.0));
  EXPECT_EQ(at(tree, "big"), PV::makeDouble(1e20));
  EXPECT_EQ(at(tree, "s1"), PV::makeString("10"));
  EXPECT_EQ(at(tree, "s2"), PV::makeString("1e-3"));
  EXPECT_EQ(at(tree, "s3"), PV::makeString("true"));
  EXPECT_EQ(at(tree, "s4"), PV::makeString("abc"));
  EXPECT_EQ(at(tree, "s5"), PV::makeString("0x10"));
  EXPECT_EQ(at(tree, "s6"), PV::makeString("1_000"));
  EXPECT_EQ(at(tree, "s7"), PV::makeString("inf"));
  EXPECT_EQ(at(tree, "s8"), PV::makeString("y"));
  EXPECT_EQ(at(tree, "s9"), PV::makeString("block\n"));
}

TEST(YamlParameters, InfinityAndNan) {
  const PV tree = yaml("a: .inf\nb: -.inf\nc: +.Inf\nd: .NaN\ne: .INF\n");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(at(tree, "a"), PV::makeDouble(inf));
  EXPECT_EQ(at(tree, "b"), PV::makeDouble(-inf));
  EXPECT_EQ(at(tree, "c"), PV::makeDouble(inf));
  EXPECT_EQ(at(tree, "e"), PV::makeDouble(inf));
  const PV nan = at(tree, "d");
  ASSERT_TRUE(nan.isDouble());
  EXPECT_TRUE(std::isnan(nan.asDouble()));
}

TEST(YamlParameters, StandardTags) {
  const PV tree = yaml("a: !!str 10\nb: !!float 10\nc: !!int 12\nd: !!bool yes\n");
  EXPECT_EQ(at(tree, "a"), PV::makeString("10"));
  EXPECT_EQ(at(tree, "b"), PV::makeDouble(10.0));
  EXPECT_EQ(at(tree, "c"), PV::makeInt(12));
  EXPECT_EQ(at(tree, "d"), PV::makeBool(true));
  EXPECT_EQ(yamlError("a: !!int 1.5\n"), "test.yaml line 1: a = '1.5' does not fit its tag int");
  EXPECT_EQ(yamlError("x:\n  a: !degrees 90\n"),
            "test.yaml line 2: x/a has the yaml tag '!degrees', which is not supported");
}

TEST(YamlParameters, NestedMapsAndLists) {
  const PV tree = yaml(
      "table:\n  size: [1.2, 0.8]\n  thickness: 0.03\n"
      "bricks:\n  - {id: a, position: [0, 0, 0.1]}\n  - id: b\n");
  PV expected;
  expected.setPath("table/size", numbers({1.2, 0.8}));
  expected.setPath("table/thickness", PV::makeDouble(0.03));
  PV first;
  first.set("id", PV::makeString("a"));
  first.set("position", PV::makeList({PV::makeInt(0), PV::makeInt(0), PV::makeDouble(0.1)}));
  PV second;
  second.set("id", PV::makeString("b"));
  expected.set("bricks", PV::makeList({first, second}));
  EXPECT_EQ(tree, expected);
}

TEST(YamlParameters, EmptyDocumentIsAnEmptyMap) {
  EXPECT_EQ(yaml(""), PV::makeMap());
  EXPECT_EQ(yaml("# only a comment\n"), PV::makeMap());
}

TEST(YamlParameters, NullIsAnErrorNamingItsPath) {
  EXPECT_EQ(yamlError("time_step: 0.001\nscene:\n"), "test.yaml line 2: scene has no value");
  EXPECT_EQ(yamlError("scene: ~\n"), "test.yaml line 1: scene has no value");
  EXPECT_EQ(yamlError("table:\n  size: null\n"), "test.yaml line 2: table/size has no value");
  EXPECT_EQ(yamlError("dirs:\n  - a\n  - ~\n"), "test.yaml line 3: dirs[1] has no value");
}

TEST(YamlParameters, TopOfTheDocumentMustBeAMap) {
  EXPECT_EQ(yamlError("- 1\n- 2\n"),
            "test.yaml: the top of the document is a list of 2, expected a map");
  EXPECT_EQ(yamlError("just text\n"),
            "test.yaml: the top of the document is string 'just text', expected a map");
}

TEST(YamlParameters, ParseErrorNamesSourceAndLine) {
  const std::string message = yamlError("a: 1\nb: [1,\nc: 2\n");
  EXPECT_EQ(message.rfind("test.yaml line ", 0), 0u) << message;
  EXPECT_NE(message.find("invalid yaml"), std::string::npos) << message;
  EXPECT_EQ(yamlError("a: b: c\n").rfind("test.yaml line 1: invalid yaml: ", 0), 0u);
}

TEST(YamlParameters, KeysMustBeUniquePlainNames) {
  EXPECT_EQ(yamlError("a: 1\ntable:\n  x: 1\n  x: 2\n"),
            "test.yaml line 4: table/x is given twice");
  EXPECT_EQ(yamlError("table/size: [1, 2]\n"),
            "test.yaml line 1: the top of the document has the key 'table/size' with a '/' in it; "
            "write nested maps instead");
  EXPECT_EQ(yamlError("? [1, 2]\n: 3\n"),
            "test.yaml line 1: the top of the document has a key that is not a plain name");
  EXPECT_EQ(yamlError("a: {'': 1}\n"), "test.yaml line 1: a has an empty key");
}

TEST(YamlParameters, MoreThanOneDocumentIsRefused) {
  EXPECT_EQ(yamlError("a: 1\n---\nb: 2\n"), "test.yaml holds 2 yaml documents, expected one");
}

TEST(YamlParameters, SelfReferencingAliasIsRefusedNotFollowed) {
  // yaml-cpp makes this a cycle; following it would never end.
  const std::string message = yamlError("a: &x [1, *x]\n");
  EXPECT_NE(message.find("is nested more than 100 levels deep"), std::string::npos) << message;
}

TEST(YamlParameters, ExponentialAliasesAreRefused) {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 7; ++i) {
    const std::string prev = "*l" + std::to_string(i - 1);
    text += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
    for (int j = 0; j < 10; ++j) text += (j ? ", " : "") + prev;
    text += "]\n";
  }
  const std::string message = yamlError(text);  // 10^8 strings if expanded
  EXPECT_NE(message.find("more than 1000000 values"), std::string::npos) << message;
}

TEST(YamlParameters, NumbersOutOfRangeOfADouble) {
  EXPECT_EQ(yamlError("a: 1e999\n"), "test.yaml line 1: a = 1e999 is out of the range of a double");
}

TEST(YamlParameters, LaterFileWinsWhenMerged) {
  PV tree = yaml("time_step: 0.001\ntable: {size: [1, 2], thickness: 0.03}\n");
  tree.merge(yaml("table: {thickness: 0.05}\n"));
  OptionsReader reader(tree);
  WorldOptions world;
  reader.read("time_step", &world.time_step);
  reader.section("table", &readTableOptions, &world.table);
  ASSERT_TRUE(reader.finish().ok);
  EXPECT_EQ(world.table.size, Eigen::Vector2d(1, 2));
  EXPECT_EQ(world.table.thickness, 0.05);
}

// ---------------------------------------------------------------------------------------------
// Files

class LoadYaml : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/test_parameter_tree_XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    for (const std::string& file : files_) std::remove(file.c_str());
    ::rmdir(dir_.c_str());
  }
  std::string file(const std::string& name, const std::string& content) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << content;
    files_.push_back(path);
    return path;
  }
  /// Loads `path` expecting a refusal; returns the message.
  std::string refused(const std::string& path, std::size_t max_bytes = 16u << 20) {
    PV tree = PV::makeInt(42);
    const Status status = loadYamlParameters(path, &tree, max_bytes);
    EXPECT_FALSE(status.ok) << path;
    EXPECT_EQ(tree, PV::makeInt(42));
    return status.message;
  }

  std::string dir_;
  std::vector<std::string> files_;
};

TEST_F(LoadYaml, LoadsAFile) {
  PV tree;
  const Status status = loadYamlParameters(file("sim.yaml", "table:\n  thickness: 0.02\n"), &tree);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(at(tree, "table/thickness"), PV::makeDouble(0.02));
}

TEST_F(LoadYaml, MessagesNameTheFile) {
  const std::string path = file("bad.yaml", "a: 1\nscene:\n");
  EXPECT_EQ(refused(path), path + " line 2: scene has no value");
}

TEST_F(LoadYaml, MissingFile) {
  EXPECT_EQ(refused(dir_ + "/absent.yaml"),
            "cannot read config '" + dir_ + "/absent.yaml': no such file");
}

TEST_F(LoadYaml, DirectoryIsNotARegularFile) {
  EXPECT_EQ(refused(dir_), "config '" + dir_ + "' is not a regular file");
}

TEST_F(LoadYaml, DeviceIsNotReadWhole) {
  // Reading /dev/zero whole would never end.
  EXPECT_EQ(refused("/dev/zero"), "config '/dev/zero' is not a regular file");
}

TEST_F(LoadYaml, FifoIsNotOpened) {
  const std::string path = dir_ + "/fifo.yaml";
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  files_.push_back(path);
  // Opening a FIFO without a writer would block.
  EXPECT_EQ(refused(path), "config '" + path + "' is not a regular file");
}

TEST_F(LoadYaml, FileOverTheLimit) {
  const std::string path = file("big.yaml", "a: " + std::string(997, 'x'));
  EXPECT_EQ(refused(path, 100), "config '" + path + "' is 1000 bytes, more than the limit of 100");
  PV tree;
  EXPECT_TRUE(loadYamlParameters(path, &tree, 1000).ok);  // the limit itself is allowed
}

TEST_F(LoadYaml, ReadingStopsAtTheLimitWhenStatDoesNotKnowTheSize) {
  // procfs files are regular files of size 0 with content: the same case as a file growing
  // between stat() and read(). Only max_bytes + 1 bytes may be read.
  const std::string path = "/proc/self/status";
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) || info.st_size != 0) {
    GTEST_SKIP() << path << " is not a regular file of size 0 here";
  }
  EXPECT_EQ(refused(path, 16), "config '/proc/self/status' is more than the limit of 16 bytes");
}

}  // namespace
}  // namespace brick_stack_sim
