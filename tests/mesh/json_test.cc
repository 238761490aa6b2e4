#include "ergo/mesh/json.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// The location an InputError names for `text`, or "" if it parses.
std::string ErrorLocation(const std::string& text) {
  try {
    ParseJson(text, "test.json");
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "test.json");
    return error.location();
  }
  return "";
}

TEST(Mesh, JsonRoundTripKeepsStructureOrderAndTypes) {
  Json value = Json::Object();
  value["format"] = "ergo-body";
  value["version"] = 1;
  value["ok"] = true;
  value["nothing"] = Json();
  value["list"].Append(1.5);
  value["list"].Append(-2);
  value["nested"]["name"] = "quote \" backslash \\ newline \n tab \t control \x01 é";
  value["nested"]["empty_array"] = Json::Array();
  value["nested"]["empty_object"] = Json::Object();
  for (int indent : {0, 2}) {
    const std::string text = WriteJson(value, indent);
    const Json back = ParseJson(text, "round trip");
    EXPECT_EQ(back, value) << text;
    EXPECT_EQ(back.AsObject().front().first, "format");  // insertion order kept
    EXPECT_EQ(back.AsObject().back().first, "nested");
  }
}

TEST(Mesh, JsonNumbersRoundTripBitExactly) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  Json list = Json::Array();
  std::vector<double> numbers = {
      0.1, 1.0 / 3.0, -0.0, 5e-324, 1.7976931348623157e308, 123456789012345678.0, 1e21, 0.0};
  for (int i = 0; i < 1000; ++i) numbers.push_back(std::ldexp(mantissa(random), exponent(random)));
  for (double x : numbers) list.Append(x);
  const Json back = ParseJson(WriteJson(list), "numbers");
  ASSERT_EQ(back.size(), numbers.size());
  for (size_t i = 0; i < numbers.size(); ++i) {
    EXPECT_EQ(back[i].AsNumber(), numbers[i]);
    EXPECT_EQ(std::signbit(back[i].AsNumber()), std::signbit(numbers[i]));
  }
  // Integers are written without a decimal point; non-finite numbers as null.
  EXPECT_EQ(WriteJson(Json(42), 0), "42");
  EXPECT_EQ(WriteJson(Json(std::numeric_limits<double>::quiet_NaN()), 0), "null");
}

TEST(Mesh, JsonParsesEscapesAndUnicode) {
  const Json value =
      ParseJson(R"( {"a": "x\u00e9\ud83d\ude00\/\"", "b": [true, false, null, -1.5e3]} )", "t");
  EXPECT_EQ(value.Find("a")->AsString(), "x\xc3\xa9\xf0\x9f\x98\x80/\"");
  EXPECT_EQ((*value.Find("b"))[3].AsNumber(), -1500.0);
  EXPECT_TRUE((*value.Find("b"))[2].is_null());
}

TEST(Mesh, JsonParseErrorsNameLineAndColumn) {
  EXPECT_EQ(ErrorLocation("{\n  \"a\": 1,\n  \"b\": ,\n}"), "line 3, column 8");
  EXPECT_EQ(ErrorLocation("{\"a\": 1,}"), "line 1, column 9");            // trailing comma
  EXPECT_EQ(ErrorLocation("[1, 2"), "line 1, column 6");                  // unterminated
  EXPECT_EQ(ErrorLocation("{\"a\": 01}"), "line 1, column 8");            // leading zero
  EXPECT_EQ(ErrorLocation("\"abc"), "line 1, column 5");                  // open string
  EXPECT_EQ(ErrorLocation("{\"a\": 1, \"a\": 2}"), "line 1, column 10");  // duplicate key
  EXPECT_EQ(ErrorLocation("[1] 2"), "line 1, column 5");                  // trailing value
  EXPECT_EQ(ErrorLocation("nul"), "line 1, column 1");
  EXPECT_EQ(ErrorLocation(""), "line 1, column 1");
  EXPECT_EQ(ErrorLocation("[1e999]"), "line 1, column 2");
  EXPECT_EQ(ErrorLocation(std::string(300, '[') + std::string(300, ']')), "line 1, column 258");
  EXPECT_EQ(ErrorLocation("[1, 2]"), "");
}

TEST(Mesh, JsonCheckedMembersNameTheMember) {
  const Json value = ParseJson(R"({"n": 2.5, "s": "x", "i": 3})", "file.json");
  EXPECT_EQ(GetNumber(value, "n", "file.json"), 2.5);
  EXPECT_EQ(GetString(value, "s", "file.json"), "x");
  EXPECT_EQ(GetInteger(value, "i", "file.json", 0, 10), 3);
  try {
    GetNumber(value, "missing", "file.json");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "member \"missing\"");
  }
  EXPECT_THROW(GetNumber(value, "s", "file.json"), InputError);
  EXPECT_THROW(GetInteger(value, "n", "file.json", 0, 10), InputError);
  EXPECT_THROW(GetInteger(value, "i", "file.json", 0, 2), InputError);
}

TEST(Mesh, JsonFileRoundTrip) {
  const std::string dir = testing::MakeScratchDir("json");
  Json value = Json::Object();
  value["pi"] = 3.141592653589793;
  WriteJsonFile(dir + "/a.json", value);
  EXPECT_EQ(ReadJsonFile(dir + "/a.json"), value);
  EXPECT_THROW(ReadJsonFile(dir + "/missing.json"), InputError);
}

}  // namespace
}  // namespace ergo
