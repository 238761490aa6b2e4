// Json: a minimal JSON value (null, bool, number, string, array, object) for ergo's own
// small files — body.json, summary.json. Objects keep their keys in insertion order so
// written files read like their writer intended. Numbers are doubles written in the
// shortest form that reads back bit-identical; parse errors name the line and column.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ergo {

class Json {
 public:
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  using Member = std::pair<std::string, Json>;

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool value) : type_(Type::kBool), bool_(value) {}
  Json(double value) : type_(Type::kNumber), number_(value) {}
  Json(int value) : Json(static_cast<double>(value)) {}
  Json(long value) : Json(static_cast<double>(value)) {}
  Json(long long value) : Json(static_cast<double>(value)) {}
  Json(unsigned value) : Json(static_cast<double>(value)) {}
  Json(unsigned long value) : Json(static_cast<double>(value)) {}
  Json(const char* value) : type_(Type::kString), string_(value) {}
  Json(std::string value) : type_(Type::kString), string_(std::move(value)) {}

  static Json Array() { return Json(Type::kArray); }
  static Json Object() { return Json(Type::kObject); }

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::kNull; }
  bool is_bool() const { return type_ == Type::kBool; }
  bool is_number() const { return type_ == Type::kNumber; }
  bool is_string() const { return type_ == Type::kString; }
  bool is_array() const { return type_ == Type::kArray; }
  bool is_object() const { return type_ == Type::kObject; }

  // Typed access; asking for the wrong type is a programming error (CHECK). Readers of
  // user files check the type first (or use the Get* helpers below).
  bool AsBool() const;
  double AsNumber() const;
  const std::string& AsString() const;
  const std::vector<Json>& AsArray() const;
  const std::vector<Member>& AsObject() const;

  // Arrays: appends (a null value becomes an empty array first).
  void Append(Json value);
  size_t size() const;  // elements of an array or members of an object, else 0
  const Json& operator[](size_t index) const;

  // Objects: the member `key`, inserted as null when missing (a null value becomes an
  // empty object first); Find returns nullptr when missing or when this is no object.
  Json& operator[](const std::string& key);
  const Json* Find(const std::string& key) const;

  bool operator==(const Json& other) const;
  bool operator!=(const Json& other) const { return !(*this == other); }

 private:
  explicit Json(Type type) : type_(type) {}

  Type type_ = Type::kNull;
  bool bool_ = false;
  double number_ = 0;
  std::string string_;
  std::vector<Json> array_;
  std::vector<Member> object_;
};

// "null", "boolean", "number", "string", "array" or "object".
const char* JsonTypeName(Json::Type type);

// The text of `value`: `indent` spaces per level and one member per line (indent > 0), or
// everything on one line (indent == 0). Non-finite numbers (not representable in JSON)
// are written as null. Ends with a newline when indent > 0.
std::string WriteJson(const Json& value, int indent = 2);

// Parses a whole JSON text (RFC 8259; nesting at most 256 deep, duplicate keys refused).
// Throws InputError(source, "line L, column C", what, fix) on malformed text.
Json ParseJson(std::string_view text, const std::string& source);

// Reads and parses a file; InputError names the file when it is missing or malformed.
Json ReadJsonFile(const std::string& path);

// Writes `value` atomically (temporary file + rename).
void WriteJsonFile(const std::string& path, const Json& value, int indent = 2);

// Members of a JSON object read from a user's file, with InputErrors naming `source` and
// the member ("member \"mesh\"") when it is missing or has the wrong type.
const Json& GetMember(const Json& object, const std::string& key, const std::string& source);
double GetNumber(const Json& object, const std::string& key, const std::string& source);
// A number that must be an integer in [min, max].
long long GetInteger(const Json& object, const std::string& key, const std::string& source,
                     long long min, long long max);
const std::string& GetString(const Json& object, const std::string& key, const std::string& source);
bool GetBool(const Json& object, const std::string& key, const std::string& source);

}  // namespace ergo
