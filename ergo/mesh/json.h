// Json: ergo's JSON value for its own small files (body.json, summary.json, checkpoints),
// nlohmann-json's insertion-ordered value, so written files read as their writer intended.
// Integers stay integers and doubles are written in the shortest form that reads back
// bit-identical. The helpers below are the only way ergo reads and writes JSON text: they
// turn every malformed file into an InputError naming the file, the line and column or the
// member, and the fix.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace ergo {

using Json = nlohmann::ordered_json;

// "null", "boolean", "number", "string", "array" or "object".
const char* JsonTypeName(Json::value_t type);
inline const char* JsonTypeName(const Json& value) { return JsonTypeName(value.type()); }

// The text of `value`: `indent` spaces per level and one member or element per line
// (indent > 0, ending with a newline), or everything on one line (indent <= 0). Non-finite
// numbers (not representable in JSON) are written as null, bytes that are not UTF-8 as
// U+FFFD.
std::string WriteJson(const Json& value, int indent = 2);

// Parses a whole JSON text (RFC 8259; arrays and objects nested at most 256 deep, duplicate
// keys and numbers beyond the double range refused). Throws InputError(source,
// "line L, column C", what, fix) on malformed text.
Json ParseJson(std::string_view text, const std::string& source);

// Reads and parses a file; InputError names the file when it is missing or malformed.
Json ReadJsonFile(const std::string& path);

// Writes `value` atomically (temporary file + rename, see atomic_file.h).
void WriteJsonFile(const std::string& path, const Json& value, int indent = 2);

// The member `key` of `object`, or nullptr when it is missing or `object` is no object.
// Use it (or GetMember) on data read from files: nlohmann's const operator[] with a missing
// key is undefined behaviour.
const Json* FindMember(const Json& object, const std::string& key);

// Members of a JSON object read from a user's file, with InputErrors naming `source` and
// the member ("member \"mesh\"") when it is missing or has the wrong type.
const Json& GetMember(const Json& object, const std::string& key, const std::string& source);
// A number, integer or not.
double GetNumber(const Json& object, const std::string& key, const std::string& source);
// A number that must be an integer in [min, max] (written as 3 or as 3.0).
long long GetInteger(const Json& object, const std::string& key, const std::string& source,
                     long long min, long long max);
const std::string& GetString(const Json& object, const std::string& key, const std::string& source);
bool GetBool(const Json& object, const std::string& key, const std::string& source);

}  // namespace ergo
