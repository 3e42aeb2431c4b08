// The path-aware JSON reader: every message names the file, the place and
// what was expected.
#include "io/json_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "io/expect_error.h"

namespace coilsim::io {
namespace {

TEST(JsonReader, MalformedJsonGivesLineAndColumn) {
  const std::string msg = errorOf([] { (void)parseJson("{\n  \"a\": 1,\n  \"b\": x\n}", "t.json"); });
  EXPECT_CONTAINS(msg, "t.json: line 3, column 8: malformed JSON");
}

TEST(JsonReader, TruncatedJsonSaysWhere) {
  const std::string msg = errorOf([] { (void)parseJson("{\"a\": [1, 2", "t.json"); });
  EXPECT_CONTAINS(msg, "t.json: line 1, column");
  EXPECT_CONTAINS(msg, "malformed JSON");
}

TEST(JsonReader, NumberBeyondDoubleNamesItsPath) {
  const std::string msg = errorOf([] { (void)parseJson("{\"rods\": [{\"x\": 1}, {\"length_mm\": 1e999}]}", "t.json"); });
  EXPECT_CONTAINS(msg, "t.json: line 1, column");
  EXPECT_CONTAINS(msg, "/rods/1/length_mm: expected a finite number, got 1e999");
}

TEST(JsonReader, DuplicateKeyIsAnError) {
  const std::string msg = errorOf([] { (void)parseJson("{\"a\": {\"b\": 1, \"b\": 2}}", "t.json"); });
  EXPECT_CONTAINS(msg, "t.json: /a/b: duplicate key");
}

TEST(JsonReader, ParsesNestedDocuments) {
  const nlohmann::json j = parseJson(R"({"a": [1, {"b": [true, null, "s"]}], "c": -2.5e3, "d": 18446744073709551615})", "t");
  EXPECT_EQ(j["a"][1]["b"][2], "s");
  EXPECT_EQ(j["c"].get<double>(), -2500.0);
  EXPECT_TRUE(j["a"][1]["b"][1].is_null());
  EXPECT_TRUE(j["d"].is_number_unsigned());
}

TEST(JsonReader, MissingFileNamesThePath) {
  const std::string msg = errorOf([] { (void)readJsonFile("/nonexistent/dir/scene.json"); });
  EXPECT_CONTAINS(msg, "/nonexistent/dir/scene.json: cannot open");
}

TEST(JsonReader, WrongTypeSaysExpectedAndGot) {
  const nlohmann::json j = parseJson(R"({"m": {"e": "abc"}})", "s.json");
  const JsonNode root(j, "s.json");
  const std::string msg = errorOf([&] { (void)root.child("m").child("e").number(Bounds::positive()); });
  EXPECT_EQ(msg, "s.json: /m/e: expected a finite number > 0, got \"abc\"");
}

TEST(JsonReader, MissingKeySaysWhatWasExpected) {
  const nlohmann::json j = parseJson(R"({"m": {}})", "s.json");
  const JsonNode root(j, "s.json");
  const std::string msg = errorOf([&] { (void)root.child("m").child("e").number(Bounds::nonNegative()); });
  EXPECT_EQ(msg, "s.json: /m/e: missing; expected a finite number >= 0");
}

TEST(JsonReader, BoundsAreCheckedAndDescribed) {
  const nlohmann::json j = parseJson(R"({"a": 30, "b": 0, "c": 2.5})", "s.json");
  const JsonNode root(j, "s.json");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("a").number(Bounds::closed(0, 25, "g/cm3")); }), "/a: expected a finite number in [0, 25] g/cm3, got 30");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("b").number(Bounds::positive()); }), "got 0");
  EXPECT_DOUBLE_EQ(root.child("c").number(Bounds::open(0, 3)), 2.5);
  EXPECT_EQ(Bounds::open(-1, 0.5).describe(), "a finite number in (-1, 0.5)");
}

TEST(JsonReader, UnknownKeyListsAllowedOnesAndGuesses) {
  const nlohmann::json j = parseJson(R"({"length": 3})", "s.json");
  const JsonNode root(j, "s.json");
  const std::string msg = errorOf([&] { root.allowKeys({"length_mm", "beams"}); });
  EXPECT_CONTAINS(msg, "s.json: /length: unknown key (did you mean \"length_mm\"?)");
  EXPECT_CONTAINS(msg, "allowed here: length_mm, beams");
}

TEST(JsonReader, IntegersRejectFractions) {
  const nlohmann::json j = parseJson(R"({"n": 20.5, "m": 20.0, "k": -1})", "s.json");
  const JsonNode root(j, "s.json");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("n").integer(1, 100); }), "/n: expected an integer in [1, 100], got 20.5");
  EXPECT_EQ(root.child("m").integer(1, 100), 20);
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("k").integer(0, 5); }), "got -1");
}

TEST(JsonReader, Vec3AndArraysNameTheElement) {
  const nlohmann::json j = parseJson(R"({"p": [1, 2], "q": [1, "x", 3], "r": [4, 5, 6]})", "s.json");
  const JsonNode root(j, "s.json");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("p").vec3(); }), "/p: expected [x, y, z]: an array of 3 numbers, got an array of 2");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("q").vec3(); }), "/q/1: expected a finite number, got \"x\"");
  const auto r = root.child("r").vec3();
  EXPECT_EQ(r[2], 6.0);
}

TEST(JsonReader, OneOfListsTheChoices) {
  const nlohmann::json j = parseJson(R"({"t": "spiral"})", "s.json");
  const JsonNode root(j, "s.json");
  EXPECT_CONTAINS(errorOf([&] { (void)root.child("t").oneOf({"straight", "helix"}); }), "/t: expected one of \"straight\", \"helix\", got \"spiral\"");
}

TEST(JsonReader, PointerSegmentsAreEscaped) {
  EXPECT_EQ(pointerSegment("a/b~c"), "a~1b~0c");
  const nlohmann::json j = parseJson(R"({"a/b": {}})", "s.json");
  const JsonNode root(j, "s.json");
  EXPECT_EQ(root.child("a/b").child("x").path(), "/a~1b/x");
  EXPECT_EQ(root.path(), "/");
}

TEST(JsonReader, LongValuesAreCutInMessages) {
  const std::string text = describeValue(nlohmann::json(std::string(200, 'z')));
  EXPECT_LE(text.size(), 48u);
  EXPECT_EQ(describeValue(nlohmann::json::array()), "an empty array");
}

}  // namespace
}  // namespace coilsim::io
