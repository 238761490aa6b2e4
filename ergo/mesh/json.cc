#include "ergo/mesh/json.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"

namespace ergo {

// ---------------------------------------------------------------------------------------
// Value

bool Json::AsBool() const {
  CHECK(is_bool()) << "JSON value is a " << JsonTypeName(type_) << ", not a boolean";
  return bool_;
}

double Json::AsNumber() const {
  CHECK(is_number()) << "JSON value is a " << JsonTypeName(type_) << ", not a number";
  return number_;
}

const std::string& Json::AsString() const {
  CHECK(is_string()) << "JSON value is a " << JsonTypeName(type_) << ", not a string";
  return string_;
}

const std::vector<Json>& Json::AsArray() const {
  CHECK(is_array()) << "JSON value is a " << JsonTypeName(type_) << ", not an array";
  return array_;
}

const std::vector<Json::Member>& Json::AsObject() const {
  CHECK(is_object()) << "JSON value is a " << JsonTypeName(type_) << ", not an object";
  return object_;
}

void Json::Append(Json value) {
  if (is_null()) type_ = Type::kArray;
  CHECK(is_array()) << "Append on a JSON " << JsonTypeName(type_);
  array_.push_back(std::move(value));
}

size_t Json::size() const {
  if (is_array()) return array_.size();
  if (is_object()) return object_.size();
  return 0;
}

const Json& Json::operator[](size_t index) const {
  CHECK(is_array()) << "indexing a JSON " << JsonTypeName(type_);
  CHECK_LT(index, array_.size());
  return array_[index];
}

Json& Json::operator[](const std::string& key) {
  if (is_null()) type_ = Type::kObject;
  CHECK(is_object()) << "member access on a JSON " << JsonTypeName(type_);
  for (Member& member : object_) {
    if (member.first == key) return member.second;
  }
  object_.emplace_back(key, Json());
  return object_.back().second;
}

const Json* Json::Find(const std::string& key) const {
  if (!is_object()) return nullptr;
  for (const Member& member : object_) {
    if (member.first == key) return &member.second;
  }
  return nullptr;
}

bool Json::operator==(const Json& other) const {
  if (type_ != other.type_) return false;
  switch (type_) {
    case Type::kNull:
      return true;
    case Type::kBool:
      return bool_ == other.bool_;
    case Type::kNumber:
      return number_ == other.number_;
    case Type::kString:
      return string_ == other.string_;
    case Type::kArray:
      return array_ == other.array_;
    case Type::kObject:
      return object_ == other.object_;
  }
  return false;
}

const char* JsonTypeName(Json::Type type) {
  switch (type) {
    case Json::Type::kNull:
      return "null";
    case Json::Type::kBool:
      return "boolean";
    case Json::Type::kNumber:
      return "number";
    case Json::Type::kString:
      return "string";
    case Json::Type::kArray:
      return "array";
    case Json::Type::kObject:
      return "object";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------
// Writing

namespace {

void WriteString(const std::string& text, std::string* out) {
  out->push_back('"');
  for (const char c : text) {
    switch (c) {
      case '"':
        *out += "\\\"";
        break;
      case '\\':
        *out += "\\\\";
        break;
      case '\n':
        *out += "\\n";
        break;
      case '\r':
        *out += "\\r";
        break;
      case '\t':
        *out += "\\t";
        break;
      case '\b':
        *out += "\\b";
        break;
      case '\f':
        *out += "\\f";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          static const char kHex[] = "0123456789abcdef";
          *out += "\\u00";
          out->push_back(kHex[(c >> 4) & 0xf]);
          out->push_back(kHex[c & 0xf]);
        } else {
          out->push_back(c);  // UTF-8 passes through unchanged
        }
    }
  }
  out->push_back('"');
}

void WriteNumber(double value, std::string* out) {
  if (!std::isfinite(value)) {
    *out += "null";
    return;
  }
  char buffer[32];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out->append(buffer, result.ptr);
}

void WriteValue(const Json& value, int indent, int depth, std::string* out) {
  const auto newline = [&](int level) {
    if (indent <= 0) return;
    out->push_back('\n');
    out->append(static_cast<size_t>(indent * level), ' ');
  };
  switch (value.type()) {
    case Json::Type::kNull:
      *out += "null";
      return;
    case Json::Type::kBool:
      *out += value.AsBool() ? "true" : "false";
      return;
    case Json::Type::kNumber:
      WriteNumber(value.AsNumber(), out);
      return;
    case Json::Type::kString:
      WriteString(value.AsString(), out);
      return;
    case Json::Type::kArray: {
      const std::vector<Json>& items = value.AsArray();
      if (items.empty()) {
        *out += "[]";
        return;
      }
      // Arrays of plain numbers stay on one line: they are vectors, not records.
      bool flat = true;
      for (const Json& item : items) flat = flat && (item.is_number() || item.is_bool());
      out->push_back('[');
      for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out->push_back(',');
        if (flat) {
          if (i > 0 && indent > 0) out->push_back(' ');
        } else {
          newline(depth + 1);
        }
        WriteValue(items[i], indent, depth + 1, out);
      }
      if (!flat) newline(depth);
      out->push_back(']');
      return;
    }
    case Json::Type::kObject: {
      const std::vector<Json::Member>& members = value.AsObject();
      if (members.empty()) {
        *out += "{}";
        return;
      }
      out->push_back('{');
      for (size_t i = 0; i < members.size(); ++i) {
        if (i > 0) out->push_back(',');
        newline(depth + 1);
        WriteString(members[i].first, out);
        *out += indent > 0 ? ": " : ":";
        WriteValue(members[i].second, indent, depth + 1, out);
      }
      newline(depth);
      out->push_back('}');
      return;
    }
  }
}

}  // namespace

std::string WriteJson(const Json& value, int indent) {
  std::string out;
  WriteValue(value, indent, 0, &out);
  if (indent > 0) out.push_back('\n');
  return out;
}

// ---------------------------------------------------------------------------------------
// Parsing

namespace {

constexpr int kMaxDepth = 256;

class Parser {
 public:
  Parser(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  Json ParseDocument() {
    SkipWhitespace();
    if (AtEnd()) Fail("the text is empty, expected a JSON value", "write a JSON value");
    Json value = ParseValue(0);
    SkipWhitespace();
    if (!AtEnd()) Fail("unexpected " + Describe() + " after the JSON value", "remove it");
    return value;
  }

 private:
  bool AtEnd() const { return pos_ >= text_.size(); }
  char Peek() const { return text_[pos_]; }

  void Advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      line_start_ = pos_ + 1;
    }
    ++pos_;
  }

  // The character at the cursor, quoted, for messages.
  std::string Describe() const {
    if (AtEnd()) return "end of text";
    const unsigned char c = static_cast<unsigned char>(Peek());
    if (c < 0x20 || c >= 0x7f) {
      char buffer[16];
      std::snprintf(buffer, sizeof buffer, "byte 0x%02x", c);
      return buffer;
    }
    return std::string("'") + static_cast<char>(c) + "'";
  }

  [[noreturn]] void Fail(const std::string& what, const std::string& fix) const {
    throw InputError(
        source_,
        "line " + std::to_string(line_) + ", column " + std::to_string(pos_ - line_start_ + 1),
        what, fix);
  }

  void SkipWhitespace() {
    while (!AtEnd() && (Peek() == ' ' || Peek() == '\t' || Peek() == '\n' || Peek() == '\r')) {
      Advance();
    }
  }

  void Expect(char c, const std::string& context) {
    SkipWhitespace();
    if (AtEnd() || Peek() != c) {
      Fail(std::string("expected '") + c + "' " + context + ", found " + Describe(),
           "check the JSON syntax");
    }
    Advance();
  }

  Json ParseValue(int depth) {
    if (depth > kMaxDepth) {
      Fail("values nested more than " + std::to_string(kMaxDepth) + " deep", "flatten the file");
    }
    SkipWhitespace();
    if (AtEnd()) Fail("the text ends where a value was expected", "complete the file");
    const char c = Peek();
    if (c == '{') return ParseObject(depth);
    if (c == '[') return ParseArray(depth);
    if (c == '"') return Json(ParseString());
    if (c == '-' || (c >= '0' && c <= '9')) return Json(ParseNumber());
    if (MatchWord("true")) return Json(true);
    if (MatchWord("false")) return Json(false);
    if (MatchWord("null")) return Json();
    Fail("unexpected " + Describe() + " where a value was expected",
         "write a number, a \"string\", true, false, null, [...] or {...}");
  }

  bool MatchWord(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    for (size_t i = 0; i < word.size(); ++i) Advance();
    return true;
  }

  Json ParseObject(int depth) {
    Advance();  // {
    Json object = Json::Object();
    SkipWhitespace();
    if (!AtEnd() && Peek() == '}') {
      Advance();
      return object;
    }
    while (true) {
      SkipWhitespace();
      if (AtEnd() || Peek() != '"') {
        Fail("expected a quoted member name, found " + Describe(),
             "quote member names and remove trailing commas");
      }
      const size_t key_line = line_, key_column = pos_ - line_start_ + 1;
      std::string key = ParseString();
      if (object.Find(key) != nullptr) {
        throw InputError(
            source_, "line " + std::to_string(key_line) + ", column " + std::to_string(key_column),
            "member \"" + key + "\" appears twice in one object", "keep one of them");
      }
      Expect(':', "after member name \"" + key + "\"");
      object[key] = ParseValue(depth + 1);
      SkipWhitespace();
      if (AtEnd()) Fail("the text ends inside an object", "close it with '}'");
      if (Peek() == ',') {
        Advance();
        continue;
      }
      if (Peek() == '}') {
        Advance();
        return object;
      }
      Fail("expected ',' or '}' in an object, found " + Describe(), "check the JSON syntax");
    }
  }

  Json ParseArray(int depth) {
    Advance();  // [
    Json array = Json::Array();
    SkipWhitespace();
    if (!AtEnd() && Peek() == ']') {
      Advance();
      return array;
    }
    while (true) {
      array.Append(ParseValue(depth + 1));
      SkipWhitespace();
      if (AtEnd()) Fail("the text ends inside an array", "close it with ']'");
      if (Peek() == ',') {
        Advance();
        continue;
      }
      if (Peek() == ']') {
        Advance();
        return array;
      }
      Fail("expected ',' or ']' in an array, found " + Describe(), "check the JSON syntax");
    }
  }

  unsigned ParseHex4() {
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      if (AtEnd()) Fail("the text ends inside a \\u escape", "write four hex digits");
      const char c = Peek();
      unsigned digit;
      if (c >= '0' && c <= '9') {
        digit = static_cast<unsigned>(c - '0');
      } else if (c >= 'a' && c <= 'f') {
        digit = static_cast<unsigned>(c - 'a' + 10);
      } else if (c >= 'A' && c <= 'F') {
        digit = static_cast<unsigned>(c - 'A' + 10);
      } else {
        Fail("\\u escape needs four hex digits, found " + Describe(), "write e.g. \\u00e9");
      }
      code = code * 16 + digit;
      Advance();
    }
    return code;
  }

  static void AppendUtf8(unsigned code, std::string* out) {
    if (code < 0x80) {
      out->push_back(static_cast<char>(code));
    } else if (code < 0x800) {
      out->push_back(static_cast<char>(0xc0 | (code >> 6)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    } else if (code < 0x10000) {
      out->push_back(static_cast<char>(0xe0 | (code >> 12)));
      out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    } else {
      out->push_back(static_cast<char>(0xf0 | (code >> 18)));
      out->push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    }
  }

  std::string ParseString() {
    Advance();  // opening quote
    std::string out;
    while (true) {
      if (AtEnd()) Fail("the text ends inside a string", "close the string with '\"'");
      const char c = Peek();
      if (c == '"') {
        Advance();
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) {
        Fail("control character " + Describe() + " inside a string",
             "escape it (\\n, \\t, \\u00XX)");
      }
      if (c != '\\') {
        out.push_back(c);
        Advance();
        continue;
      }
      Advance();  // backslash
      if (AtEnd()) Fail("the text ends inside an escape", "close the string");
      const char e = Peek();
      switch (e) {
        case '"':
        case '\\':
        case '/':
          out.push_back(e);
          break;
        case 'b':
          out.push_back('\b');
          break;
        case 'f':
          out.push_back('\f');
          break;
        case 'n':
          out.push_back('\n');
          break;
        case 'r':
          out.push_back('\r');
          break;
        case 't':
          out.push_back('\t');
          break;
        case 'u': {
          Advance();
          unsigned code = ParseHex4();
          if (code >= 0xd800 && code < 0xdc00) {
            if (text_.substr(pos_, 2) != "\\u") {
              Fail("a high surrogate \\u escape must be followed by a low one",
                   "write the character as a surrogate pair or in UTF-8");
            }
            Advance();
            Advance();
            const unsigned low = ParseHex4();
            if (low < 0xdc00 || low >= 0xe000) {
              Fail("invalid low surrogate in a \\u escape pair", "fix the escape");
            }
            code = 0x10000 + ((code - 0xd800) << 10) + (low - 0xdc00);
          } else if (code >= 0xdc00 && code < 0xe000) {
            Fail("a low surrogate \\u escape without a high one", "fix the escape");
          }
          AppendUtf8(code, &out);
          continue;  // ParseHex4 already advanced
        }
        default:
          Fail("unknown escape \\" + std::string(1, e) + " in a string",
               "use \\\" \\\\ \\/ \\b \\f \\n \\r \\t or \\uXXXX");
      }
      Advance();
    }
  }

  double ParseNumber() {
    const size_t start = pos_;
    // Check the strict JSON grammar first: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
    size_t i = pos_;
    const auto digit = [&](size_t k) {
      return k < text_.size() && text_[k] >= '0' && text_[k] <= '9';
    };
    if (i < text_.size() && text_[i] == '-') ++i;
    if (!digit(i)) {
      pos_ = i;
      Fail("a number needs a digit here, found " + Describe(), "write e.g. -0.5 or 12");
    }
    if (text_[i] == '0') {
      ++i;
      if (digit(i)) {
        pos_ = i;
        Fail("numbers may not have leading zeros", "write e.g. 7 instead of 07");
      }
    } else {
      while (digit(i)) ++i;
    }
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      if (!digit(i)) {
        pos_ = i;
        Fail("a decimal point must be followed by digits", "write e.g. 1.0");
      }
      while (digit(i)) ++i;
    }
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      ++i;
      if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
      if (!digit(i)) {
        pos_ = i;
        Fail("an exponent needs digits", "write e.g. 1e-3");
      }
      while (digit(i)) ++i;
    }
    double value = 0;
    const std::from_chars_result result =
        std::from_chars(text_.data() + start, text_.data() + i, value);
    if (result.ec == std::errc::result_out_of_range) {
      // from_chars leaves `value` unset on range errors: underflow is 0, overflow refused.
      bool underflow = false;
      for (size_t k = start; k < i; ++k) {
        if (text_[k] == 'e' || text_[k] == 'E') underflow = k + 1 < i && text_[k + 1] == '-';
      }
      if (!underflow) Fail("number out of the double range", "use a smaller magnitude");
      value = text_[start] == '-' ? -0.0 : 0.0;
    } else {
      CHECK(result.ec == std::errc() && result.ptr == text_.data() + i);
    }
    while (pos_ < i) Advance();
    return value;
  }

  std::string_view text_;
  const std::string& source_;
  size_t pos_ = 0;
  size_t line_ = 1;
  size_t line_start_ = 0;
};

}  // namespace

Json ParseJson(std::string_view text, const std::string& source) {
  return Parser(text, source).ParseDocument();
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

const Json& GetMember(const Json& object, const std::string& key, const std::string& source) {
  if (!object.is_object()) {
    throw InputError(source, "",
                     "expected a JSON object, found a " + std::string(JsonTypeName(object.type())),
                     "regenerate the file");
  }
  const Json* member = object.Find(key);
  if (member == nullptr) {
    throw InputError(source, "member \"" + key + "\"", "missing", "regenerate the file");
  }
  return *member;
}

namespace {

[[noreturn]] void WrongType(const Json& value, const std::string& key, const std::string& source,
                            const char* expected) {
  throw InputError(
      source, "member \"" + key + "\"",
      std::string("expected a ") + expected + ", found a " + JsonTypeName(value.type()),
      "regenerate the file");
}

}  // namespace

double GetNumber(const Json& object, const std::string& key, const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_number()) WrongType(value, key, source, "number");
  return value.AsNumber();
}

long long GetInteger(const Json& object, const std::string& key, const std::string& source,
                     long long min, long long max) {
  const double value = GetNumber(object, key, source);
  if (!(value >= static_cast<double>(min) && value <= static_cast<double>(max)) ||
      value != std::floor(value)) {
    throw InputError(
        source, "member \"" + key + "\"",
        "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]",
        "regenerate the file");
  }
  return static_cast<long long>(value);
}

const std::string& GetString(const Json& object, const std::string& key,
                             const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_string()) WrongType(value, key, source, "string");
  return value.AsString();
}

bool GetBool(const Json& object, const std::string& key, const std::string& source) {
  const Json& value = GetMember(object, key, source);
  if (!value.is_bool()) WrongType(value, key, source, "boolean");
  return value.AsBool();
}

}  // namespace ergo
