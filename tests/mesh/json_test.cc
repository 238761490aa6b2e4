// ergo's JSON helpers over nlohmann-json: written text reads back as the same value (keys
// in order, doubles bit for bit, integers as integers), and every malformed file or member
// is an InputError naming the file, the line and column or the member, and the fix.

#include "ergo/mesh/json.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// The InputError ParseJson throws for `text` (source "test.json"); fails when it parses.
InputError ParseError(const std::string& text) {
  try {
    ParseJson(text, "test.json");
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "test.json");
    return error;
  }
  ADD_FAILURE() << "parsed: " << text;
  return InputError("", "", "", "");
}

std::string ErrorLocation(const std::string& text) { return ParseError(text).location(); }

// The InputError `read` throws, or a failure.
template <typename Read>
InputError ReadError(Read read) {
  try {
    read();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "", "");
}

std::vector<std::string> Keys(const Json& object) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : object.items()) keys.push_back(key);
  return keys;
}

TEST(Mesh, JsonRoundTripKeepsStructureOrderAndTypes) {
  Json value = Json::object();
  value["format"] = "ergo-body";
  value["version"] = 1;
  value["ok"] = true;
  value["nothing"] = nullptr;
  value["list"].push_back(1.5);
  value["list"].push_back(-2);
  value["list"].push_back(Json::object({{"z", 1}, {"a", Json::array({1, 2})}}));
  value["nested"]["name"] = "quote \" backslash \\ newline \n tab \t control \x01 é";
  value["nested"]["empty_array"] = Json::array();
  value["nested"]["empty_object"] = Json::object();
  value["a_last"] = 0;
  for (int indent : {0, 2}) {
    const std::string text = WriteJson(value, indent);
    const Json back = ParseJson(text, "round trip");
    EXPECT_EQ(back, value) << text;
    // Insertion order, not alphabetical, at every level.
    EXPECT_EQ(Keys(back), (std::vector<std::string>{"format", "version", "ok", "nothing", "list",
                                                    "nested", "a_last"}));
    EXPECT_EQ(Keys(back.at("list").at(2)), (std::vector<std::string>{"z", "a"}));
    EXPECT_EQ(Keys(back.at("nested")),
              (std::vector<std::string>{"name", "empty_array", "empty_object"}));
    EXPECT_TRUE(back.at("version").is_number_integer());
    EXPECT_TRUE(back.at("list").at(0).is_number_float());
  }
}

TEST(Mesh, JsonWritesOneLineOrIndentedEndingWithANewline) {
  Json value = Json::object();
  value["a"] = 1;
  value["b"] = Json::array({true, "x"});
  EXPECT_EQ(WriteJson(value, 0), R"({"a":1,"b":[true,"x"]})");
  EXPECT_EQ(WriteJson(value), "{\n  \"a\": 1,\n  \"b\": [\n    true,\n    \"x\"\n  ]\n}\n");
  // Bytes that are not UTF-8 (a Latin-1 file name) still give valid JSON.
  EXPECT_EQ(WriteJson(Json("caf\xe9"), 0), "\"caf\xef\xbf\xbd\"");
}

TEST(Mesh, JsonNumbersRoundTripBitExactly) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<double> numbers = {0.1,
                                 1.0 / 3.0,
                                 -0.0,
                                 1e-300,
                                 5e-324,
                                 1.7976931348623157e308,
                                 123456789012345678.0,
                                 9007199254740993.0,  // 2^53 + 1 rounds to 2^53
                                 1e21,
                                 3.0,
                                 0.0};
  for (int i = 0; i < 1000; ++i) numbers.push_back(std::ldexp(mantissa(random), exponent(random)));
  Json list = Json::array();
  for (double x : numbers) list.push_back(x);
  for (int indent : {0, 2}) {
    const Json back = ParseJson(WriteJson(list, indent), "numbers");
    ASSERT_EQ(back.size(), numbers.size());
    for (size_t i = 0; i < numbers.size(); ++i) {
      const double x = back[i].get<double>();
      EXPECT_EQ(x, numbers[i]) << i;
      EXPECT_EQ(std::signbit(x), std::signbit(numbers[i])) << i;
    }
  }
  // Integers are written as integers, exactly, over the whole 64-bit range; a double stays
  // a double even when its value is whole.
  EXPECT_EQ(WriteJson(Json(42), 0), "42");
  EXPECT_EQ(WriteJson(Json(-7L), 0), "-7");
  EXPECT_EQ(WriteJson(Json(std::numeric_limits<std::int64_t>::min()), 0), "-9223372036854775808");
  EXPECT_EQ(WriteJson(Json(std::numeric_limits<std::uint64_t>::max()), 0), "18446744073709551615");
  EXPECT_EQ(ParseJson("18446744073709551615", "t").get<std::uint64_t>(),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(WriteJson(Json(3.0), 0), "3.0");
  EXPECT_EQ(WriteJson(Json(-0.0), 0), "-0.0");
  EXPECT_EQ(WriteJson(Json(0.1), 0), "0.1");
  EXPECT_EQ(WriteJson(Json(1e-300), 0), "1e-300");
  // Non-finite numbers are not JSON: written as null.
  EXPECT_EQ(WriteJson(Json(std::numeric_limits<double>::quiet_NaN()), 0), "null");
  EXPECT_EQ(WriteJson(Json::array({std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()}),
                      0),
            "[null,null]");
}

TEST(Mesh, JsonParsesEscapesAndUnicode) {
  const Json value =
      ParseJson(R"( {"a": "x\u00e9\ud83d\ude00\/\"", "b": [true, false, null, -1.5e3]} )", "t");
  EXPECT_EQ(GetString(value, "a", "t"), "x\xc3\xa9\xf0\x9f\x98\x80/\"");
  const Json& b = GetMember(value, "b", "t");
  EXPECT_EQ(b.at(3).get<double>(), -1500.0);
  EXPECT_TRUE(b.at(2).is_null());
  EXPECT_EQ(FindMember(value, "missing"), nullptr);
  EXPECT_EQ(FindMember(b, "a"), nullptr);  // not an object
  ASSERT_NE(FindMember(value, "b"), nullptr);
  EXPECT_EQ(FindMember(value, "b")->size(), 4u);
}

TEST(Mesh, JsonParseErrorsNameLineAndColumn) {
  EXPECT_EQ(ErrorLocation("{\n  \"a\": 1,\n  \"b\": ,\n}"), "line 3, column 8");
  EXPECT_EQ(ErrorLocation("{\"a\": 1,}"), "line 1, column 9");  // trailing comma
  EXPECT_EQ(ErrorLocation("[1, 2,]"), "line 1, column 7");
  EXPECT_EQ(ErrorLocation("[1, 2"), "line 1, column 6");        // unterminated
  EXPECT_EQ(ErrorLocation("{\"a\": 01}"), "line 1, column 8");  // leading zero
  EXPECT_EQ(ErrorLocation("\"abc"), "line 1, column 5");        // open string
  EXPECT_EQ(ErrorLocation("[1] 2"), "line 1, column 5");        // trailing value
  EXPECT_EQ(ErrorLocation("nul"), "line 1, column 4");          // where it stops matching
  EXPECT_EQ(ErrorLocation(""), "line 1, column 1");
  EXPECT_EQ(ErrorLocation("[1e999]"), "line 1, column 2");  // beyond the double range
  EXPECT_EQ(ErrorLocation("{\n\"a\" 1}"), "line 2, column 5");

  // The words say what is wrong and how to fix it.
  const InputError comma = ParseError("{\"a\": 1,}");
  EXPECT_EQ(comma.problem(), "expected a quoted member name, found '}'");
  EXPECT_EQ(comma.fix(), "remove the trailing comma");
  EXPECT_EQ(std::string(comma.what()),
            "test.json:line 1, column 9: expected a quoted member name, found '}' "
            "(fix: remove the trailing comma)");
  EXPECT_EQ(ParseError("[1, 2").problem(), "the text ends inside an array");
  EXPECT_EQ(ParseError("{\"a\": 01}").problem(), "numbers may not have leading zeros");
  EXPECT_EQ(ParseError("\"abc").problem(), "the string is not closed");
  EXPECT_EQ(ParseError("[1] 2").problem(), "found a number after the JSON value");
  EXPECT_EQ(ParseError(" ").problem(), "the text is empty, expected a JSON value");
  EXPECT_EQ(ParseError("[1e999]").problem(), "number 1e999 is beyond the double range");
  EXPECT_EQ(ParseError("[\"a\x01\"]").problem(), "control character U+0001 (SOH) inside a string");
  EXPECT_EQ(ParseError("{\"a\" 1}").problem(),
            "expected ':' after the member name, found a number");
  EXPECT_EQ(ParseError("[\"\\q\"]").problem(), "unknown escape after '\\' in a string");
  EXPECT_EQ(ParseError("[1.]").problem(), "a decimal point must be followed by digits");
  for (const char* text : {"{\"a\": 1,}", "[1, 2", "nul", "[\"\xff\"]", "{1: 2}", "[1 2]"})
    EXPECT_FALSE(ParseError(text).fix().empty()) << text;
}

TEST(Mesh, JsonRefusesDuplicateKeysNamingTheKeyAndBothPlaces) {
  const InputError error = ParseError("{\n  \"a\": 1,\n  \"b\": {\"a\": 2},\n  \"a\": 3\n}");
  EXPECT_EQ(error.location(), "line 4, column 3");
  EXPECT_EQ(error.problem(),
            "member \"a\" appears twice in one object (first at line 2, column 3)");
  EXPECT_EQ(error.fix(), "keep one of them");
  // The same key in different objects is fine, and escaped quotes do not confuse the column.
  EXPECT_NO_THROW(ParseJson(R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}}])", "t"));
  EXPECT_EQ(ErrorLocation(R"({"x\"y": 1, "x\"y": 2})"), "line 1, column 13");
}

TEST(Mesh, JsonRefusesNestingDeeperThan256) {
  const auto nested = [](int depth, char open, char close) {
    return std::string(static_cast<size_t>(depth), open) +
           std::string(static_cast<size_t>(depth), close);
  };
  EXPECT_NO_THROW(ParseJson(nested(256, '[', ']'), "t"));
  EXPECT_EQ(ErrorLocation(nested(257, '[', ']')), "line 1, column 257");
  EXPECT_EQ(ErrorLocation(nested(100000, '[', ']')), "line 1, column 257");
  std::string objects;
  for (int i = 0; i < 300; ++i) objects += "{\"k\":";
  const InputError error = ParseError(objects + "1" + std::string(300, '}'));
  EXPECT_EQ(error.location(), "line 1, column " + std::to_string(256 * 5 + 1));
  EXPECT_EQ(error.problem(), "arrays and objects nested more than 256 deep");
}

TEST(Mesh, JsonCheckedMembersNameTheMemberAndTheSource) {
  const Json value =
      ParseJson(R"({"n": 2.5, "s": "x", "i": 3, "w": 4.0, "b": true, "l": [1]})", "file.json");
  EXPECT_EQ(GetNumber(value, "n", "file.json"), 2.5);
  EXPECT_EQ(GetNumber(value, "i", "file.json"), 3.0);  // integers are numbers too
  EXPECT_EQ(GetString(value, "s", "file.json"), "x");
  EXPECT_TRUE(GetBool(value, "b", "file.json"));
  EXPECT_EQ(GetInteger(value, "i", "file.json", 0, 10), 3);
  EXPECT_EQ(GetInteger(value, "w", "file.json", 0, 10), 4);  // a whole double
  EXPECT_EQ(GetMember(value, "l", "file.json").size(), 1u);

  InputError missing = ReadError([&] { GetNumber(value, "missing", "file.json"); });
  EXPECT_EQ(missing.source(), "file.json");
  EXPECT_EQ(missing.location(), "member \"missing\"");
  EXPECT_EQ(missing.problem(), "missing");

  InputError wrong = ReadError([&] { GetNumber(value, "s", "file.json"); });
  EXPECT_EQ(std::string(wrong.what()),
            "file.json:member \"s\": expected a number, found a string (fix: regenerate the file)");
  EXPECT_EQ(ReadError([&] { GetString(value, "l", "file.json"); }).problem(),
            "expected a string, found an array");
  EXPECT_EQ(ReadError([&] { GetBool(value, "i", "file.json"); }).problem(),
            "expected a boolean, found a number");
  EXPECT_EQ(ReadError([&] { GetMember(Json::array(), "x", "file.json"); }).problem(),
            "expected a JSON object, found an array");

  EXPECT_EQ(ReadError([&] { GetInteger(value, "n", "file.json", 0, 10); }).problem(),
            "expected an integer in [0, 10], found 2.5");
  EXPECT_EQ(ReadError([&] { GetInteger(value, "i", "file.json", 0, 2); }).problem(),
            "expected an integer in [0, 2], found 3");
  EXPECT_EQ(ReadError([&] { GetInteger(value, "s", "file.json", 0, 2); }).location(),
            "member \"s\"");
  const Json extremes = ParseJson(R"({"huge": 1e300, "u": 18446744073709551615, "m": -4})", "t");
  EXPECT_THROW(GetInteger(extremes, "huge", "t", 0, std::numeric_limits<long long>::max()),
               InputError);
  EXPECT_THROW(GetInteger(extremes, "u", "t", 0, std::numeric_limits<long long>::max()),
               InputError);
  EXPECT_EQ(GetInteger(extremes, "m", "t", -10, 0), -4);
}

TEST(Mesh, JsonFileRoundTripAndErrorsNameTheFile) {
  const std::string dir = testing::MakeScratchDir("json");
  Json value = Json::object();
  value["pi"] = 3.141592653589793;
  value["n"] = 7;
  WriteJsonFile(dir + "/a.json", value);
  EXPECT_EQ(ReadJsonFile(dir + "/a.json"), value);

  const InputError missing = ReadError([&] { ReadJsonFile(dir + "/missing.json"); });
  EXPECT_EQ(missing.source(), dir + "/missing.json");
  EXPECT_EQ(missing.problem(), "cannot open the file");

  std::ofstream(dir + "/bad.json") << "{\n  \"pi\": 3.14,\n  \"n\": 7\n";
  const InputError bad = ReadError([&] { ReadJsonFile(dir + "/bad.json"); });
  EXPECT_EQ(bad.source(), dir + "/bad.json");
  EXPECT_EQ(bad.location(), "line 4, column 1");
  EXPECT_EQ(bad.problem(), "the text ends inside an object");
}

TEST(Mesh, JsonFileWriteIsAtomic) {
  const std::string dir = testing::MakeScratchDir("json");
  const std::string path = dir + "/out.json";
  std::ofstream(path) << "old content, longer than the new one, that must not survive in part";
  WriteJsonFile(path, Json::object({{"new", true}}), 0);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, R"({"new":true})");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // no temporary file left behind

  const std::string unwritable = dir + "/missing/folder/out.json";
  EXPECT_EQ(ReadError([&] { WriteJsonFile(unwritable, Json::object()); }).source(), unwritable);
  EXPECT_FALSE(fs::exists(dir + "/missing"));
}

}  // namespace
}  // namespace ergo
