#include "ergo/mesh/json.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"

namespace ergo {

const char* JsonTypeName(Json::value_t type) {
  switch (type) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "number";
    case Json::value_t::string:
      return "string";
    case Json::value_t::array:
      return "array";
    case Json::value_t::object:
      return "object";
    case Json::value_t::binary:
      return "binary";
    case Json::value_t::discarded:
      return "discarded";
  }
  return "?";
}

std::string WriteJson(const Json& value, int indent) {
  std::string text = value.dump(indent > 0 ? indent : -1, ' ', /*ensure_ascii=*/false,
                                Json::error_handler_t::replace);
  if (indent > 0) text.push_back('\n');
  return text;
}

// ---------------------------------------------------------------------------------------
// Parsing: nlohmann's parser, its errors and positions in ergo's words.

namespace {

constexpr int kMaxDepth = 256;
constexpr char kValueFix[] = "write a number, a \"string\", true, false, null, [...] or {...}";

// "line L, column C" of the byte at `offset` (0-based; text.size() is just past the end).
std::string LineAndColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, line_start = 0;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(offset - line_start + 1);
}

// Hands `text` to nlohmann's lexer and counts the bytes it has read: the parser callback is
// told no position, so its errors (duplicate keys, nesting) are placed with this count.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* at, const char* begin, size_t* read)
      : at_(at), begin_(begin), read_(read) {}

  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    *read_ = static_cast<size_t>(at_ - begin_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* at_;
  const char* begin_;
  size_t* read_;
};

// The opening quote of the string whose closing quote is at `close`.
size_t StringStart(std::string_view text, size_t close) {
  for (size_t i = close; i-- > 0;) {
    if (text[i] != '"') continue;
    size_t backslashes = 0;
    while (backslashes < i && text[i - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return 0;
}

bool InNumber(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// The first byte of the number the lexer has just read, `read` bytes into the text (the
// lexer reads one byte past a number unless the text ends).
size_t NumberStart(std::string_view text, size_t read) {
  size_t i = std::min(read, text.size());
  if (i > 0 && !InNumber(text[i - 1])) --i;
  while (i > 0 && InNumber(text[i - 1])) --i;
  return i;
}

// The last byte before `offset` that is not white space, or '\0'.
char PreviousVisible(std::string_view text, size_t offset) {
  for (size_t i = std::min(offset, text.size()); i-- > 0;) {
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n' && text[i] != '\r') return text[i];
  }
  return '\0';
}

// nlohmann's name of a token in plain words.
std::string TokenWords(std::string_view token) {
  if (token == "string literal") return "a string";
  if (token == "number literal") return "a number";
  if (token == "true literal") return "true";
  if (token == "false literal") return "false";
  if (token == "null literal") return "null";
  return std::string(token);  // "'}'", "','", ...
}

struct Problem {
  std::string what, fix;
};

// The part of `text` after `after` and before `before` (to the end when `before` is empty
// or missing).
std::string_view Between(std::string_view text, std::string_view after,
                         std::string_view before = {}) {
  size_t begin = text.find(after);
  if (begin == std::string_view::npos) return {};
  begin += after.size();
  const size_t end = before.empty() ? std::string_view::npos : text.find(before, begin);
  return text.substr(begin, end == std::string_view::npos ? end : end - begin);
}

// What nlohmann's parse_error message (`message`, detected at byte `offset` of `text`)
// means for someone editing the file, and how to fix it.
Problem DescribeParseError(std::string_view text, size_t offset, std::string_view message) {
  // "... syntax error while parsing CONTEXT - DETAIL", DETAIL either "unexpected TOKEN[;
  // expected TOKEN]" or "LEXER MESSAGE; last read: '...'".
  const std::string_view context = Between(message, "while parsing ", " - ");
  const size_t dash = message.find(" - ");
  const std::string_view detail =
      dash == std::string_view::npos ? message : message.substr(dash + 3);
  if (detail.rfind("unexpected ", 0) == 0) {
    const std::string_view token = Between(detail, "unexpected ", "; expected ");
    const std::string_view expected = Between(detail, "; expected ");
    const std::string found = TokenWords(token);
    if (token == "end of input") {
      if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
        return {"the text is empty, expected a JSON value", "write a JSON value"};
      }
      if (context == "array") {
        return {"the text ends inside an array",
                "close it with ']'; the file may have been cut short"};
      }
      if (context.rfind("object", 0) == 0) {
        return {"the text ends inside an object",
                "close it with '}'; the file may have been cut short"};
      }
      return {"the text ends where a value was expected",
              "complete the file; it may have been cut short"};
    }
    if (expected == "end of input") {
      return {"found " + found + " after the JSON value", "remove it: a file holds one JSON value"};
    }
    if (token == "number literal" && offset < text.size()) {
      // "01" reads as the number 0 followed by the number 1.
      size_t start = offset;
      const auto digit = [](char c) { return c >= '0' && c <= '9'; };
      while (start > 0 && text[start - 1] >= '1' && text[start - 1] <= '9') --start;
      if (start > 0 && text[start - 1] == '0' &&
          (start < 2 || !(digit(text[start - 2]) || text[start - 2] == '.'))) {
        return {"numbers may not have leading zeros", "write e.g. 7 instead of 07"};
      }
    }
    const bool trailing_comma = PreviousVisible(text, offset) == ',';
    if (context == "object key") {
      if (token == "'}'" && trailing_comma) {
        return {"expected a quoted member name, found '}'", "remove the trailing comma"};
      }
      return {"expected a quoted member name, found " + found,
              "quote member names: {\"name\": value}"};
    }
    if (context == "object separator") {
      return {"expected ':' after the member name, found " + found, "write \"name\": value"};
    }
    if (context == "object") {
      return {"expected ',' or '}' after a member, found " + found, "separate members with commas"};
    }
    if (context == "array") {
      return {"expected ',' or ']' after an element, found " + found,
              "separate elements with commas"};
    }
    if (token == "']'" && trailing_comma) {
      return {"expected a value, found ']'", "remove the trailing comma"};
    }
    return {"expected a value, found " + found, kValueFix};
  }
  // A lexer error: the token itself is malformed.
  const std::string_view lexer = detail.substr(0, detail.find("; last read: "));
  if (lexer == "invalid literal") {
    return {
        "unexpected text where a value was expected (true, false and null are lower case, "
        "strings need double quotes)",
        kValueFix};
  }
  if (lexer == "invalid string: missing closing quote") {
    return {"the string is not closed", "close it with '\"'"};
  }
  if (lexer.rfind("invalid string: control character", 0) == 0) {
    const std::string_view name = Between(lexer, "invalid string: ", " must be escaped to ");
    const std::string_view escape = Between(lexer, " must be escaped to ");
    return {std::string(name) + " inside a string", "write it as " + std::string(escape)};
  }
  if (lexer == "invalid string: forbidden character after backslash") {
    return {"unknown escape after '\\' in a string",
            "use \\\" \\\\ \\/ \\b \\f \\n \\r \\t or \\uXXXX"};
  }
  if (lexer == "invalid string: ill-formed UTF-8 byte") {
    return {"a string holds a byte that is not UTF-8", "save the file as UTF-8"};
  }
  if (lexer == "invalid number; expected digit after '.'") {
    return {"a decimal point must be followed by digits", "write e.g. 1.0"};
  }
  if (lexer == "invalid number; expected digit after exponent sign" ||
      lexer == "invalid number; expected '+', '-', or digit after exponent") {
    return {"an exponent needs digits", "write e.g. 1e-3"};
  }
  if (lexer.rfind("invalid number", 0) == 0) {
    return {"a number needs a digit here", "write e.g. -0.5 or 12"};
  }
  return {std::string(lexer), "check the JSON syntax"};  // rare: unicode escapes, a BOM
}

}  // namespace

Json ParseJson(std::string_view text, const std::string& source) {
  size_t read = 0;  // bytes the lexer has read
  // The keys of each open object, with where each first appeared.
  std::vector<std::unordered_map<std::string, size_t>> keys;
  const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        // `depth` counts the enclosing arrays and objects; the bracket was the last byte read.
        if (depth >= kMaxDepth) {
          throw InputError(
              source, LineAndColumn(text, read - 1),
              "arrays and objects nested more than " + std::to_string(kMaxDepth) + " deep",
              "flatten the file");
        }
        if (event == Json::parse_event_t::object_start) keys.emplace_back();
        break;
      case Json::parse_event_t::key: {
        // The key's closing quote was the last byte read.
        const std::string& key = parsed.get_ref<const std::string&>();
        const size_t start = StringStart(text, read - 1);
        const auto [first, inserted] = keys.back().emplace(key, start);
        if (!inserted) {
          throw InputError(source, LineAndColumn(text, start),
                           "member \"" + key + "\" appears twice in one object (first at " +
                               LineAndColumn(text, first->second) + ")",
                           "keep one of them");
        }
        break;
      }
      case Json::parse_event_t::object_end:
        keys.pop_back();
        break;
      default:
        break;
    }
    return true;
  };
  const char* begin = text.data();
  try {
    return Json::parse(CountingIterator(begin, begin, &read),
                       CountingIterator(begin + text.size(), begin, &read), check);
  } catch (const Json::parse_error& error) {
    // error.byte counts the bytes read including the offending one (and the end of text).
    const size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    const Problem problem = DescribeParseError(text, offset, error.what());
    throw InputError(source, LineAndColumn(text, offset), problem.what, problem.fix);
  } catch (const Json::out_of_range& error) {
    if (error.id != 406) throw;
    // A number beyond the double range ("1e999"); nlohmann names no position, but the
    // lexer has just read the number.
    const size_t start = NumberStart(text, read);
    size_t end = start;
    while (end < text.size() && InNumber(text[end])) ++end;
    throw InputError(
        source, LineAndColumn(text, start),
        "number " + std::string(text.substr(start, end - start)) + " is beyond the double range",
        "use a smaller magnitude");
  }
}

Json ReadJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the file", "check the path");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "reading failed", "check the file");
  return ParseJson(buffer.str(), path);
}

void WriteJsonFile(const std::string& path, const Json& value, int indent) {
  const std::string text = WriteJson(value, indent);
  WriteFileAtomically(path, [&](std::ostream& out) { out << text; });
}

// ---------------------------------------------------------------------------------------
// Checked member access

const Json* FindMember(const Json& object, const std::string& key) {
  if (!object.is_object()) return nullptr;
  const auto member = object.find(key);
  return member == object.end() ? nullptr : &*member;
}

namespace {

// "null", "a number", "an array", ... for messages.
std::string WithArticle(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::object:
      return "an object";
    default:
      return std::string("a ") + JsonTypeName(value);
  }
}

[[noreturn]] void WrongType(const Json& value, const std::string& key, const std::string& source,
                            const char* expected) {
  throw InputError(source, "member \"" + key + "\"",
                   std::string("expected ") + expected + ", found " + WithArticle(value),
                   "regenerate the file");
}

}  // namespace

const Json& GetMember(const Json& object, const std::string& key, const std::string& source) {
  if (!object.is_object()) {
    throw InputError(source, "", "expected a JSON object, found " + WithArticle(object),
                     "regenerate the file");
  }
  const Json* member = FindMember(object, key);
  if (member == nullptr) {
    throw InputError(source, "member \"" + key + "\"", "missing", "regenerate the file");
  }
  return *member;
}

double GetNumber(const Json& object, const std::string& key, const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_number()) WrongType(value, key, source, "a number");
  return value.get<double>();
}

long long GetInteger(const Json& object, const std::string& key, const std::string& source,
                     long long min, long long max) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_number()) WrongType(value, key, source, "an integer");
  bool integer = false;
  long long n = 0;
  if (value.is_number_unsigned()) {
    const auto u = value.get<Json::number_unsigned_t>();
    integer = u <= static_cast<Json::number_unsigned_t>(std::numeric_limits<long long>::max());
    n = static_cast<long long>(u);
  } else if (value.is_number_integer()) {
    n = value.get<Json::number_integer_t>();
    integer = true;
  } else {
    // A double such as 3.0; [-2^63, 2^63) is where the conversion is defined.
    const double x = value.get<double>();
    integer = x == std::floor(x) && x >= -0x1p63 && x < 0x1p63;
    if (integer) n = static_cast<long long>(x);
  }
  if (!integer || n < min || n > max) {
    throw InputError(source, "member \"" + key + "\"",
                     "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                         "], found " + WriteJson(value, 0),
                     "regenerate the file");
  }
  return n;
}

const std::string& GetString(const Json& object, const std::string& key,
                             const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_string()) WrongType(value, key, source, "a string");
  return value.get_ref<const std::string&>();
}

bool GetBool(const Json& object, const std::string& key, const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_boolean()) WrongType(value, key, source, "a boolean");
  return value.get<bool>();
}

}  // namespace ergo
