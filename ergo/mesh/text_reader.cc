#include "ergo/mesh/text_reader.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "ergo/mesh/input_error.h"

namespace ergo {

namespace fs = std::filesystem;

namespace {

constexpr uintmax_t kMaxFileBytes = uintmax_t{1} << 31;

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || c == '\n';
}

}  // namespace

std::string ReadFileBytes(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || !fs::exists(status)) {
    throw InputError(path, "", "the file does not exist or cannot be accessed",
                     "check the path and its permissions");
  }
  if (fs::is_directory(status)) {
    throw InputError(path, "", "this is a directory, not a mesh file", "pass a mesh file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path, "", "the file cannot be opened for reading", "check its permissions");
  }
  // Read in chunks rather than trusting a size query, which lies for pipes and /proc files.
  std::string bytes;
  char chunk[1 << 16];
  while (in) {
    in.read(chunk, sizeof chunk);
    bytes.append(chunk, static_cast<size_t>(in.gcount()));
    if (bytes.size() > kMaxFileBytes) {
      throw InputError(path, "", "the file is larger than 2 GiB",
                       "split the mesh or decimate it; ergo reads meshes up to 2 GiB");
    }
  }
  if (in.bad()) {
    throw InputError(path, "", "a read error occurred", "check the disk and the file");
  }
  if (bytes.empty()) {
    throw InputError(path, "", "the file is empty (0 bytes)",
                     "re-export the mesh; the writer may have failed");
  }
  return bytes;
}

std::string BytesToText(std::string bytes, bool* was_utf16) {
  if (was_utf16) *was_utf16 = false;
  if (bytes.size() >= 3 && static_cast<unsigned char>(bytes[0]) == 0xEF &&
      static_cast<unsigned char>(bytes[1]) == 0xBB &&
      static_cast<unsigned char>(bytes[2]) == 0xBF) {
    return bytes.substr(3);
  }
  if (bytes.size() >= 2) {
    const unsigned char b0 = bytes[0], b1 = bytes[1];
    const bool big_endian = b0 == 0xFE && b1 == 0xFF;
    const bool little_endian = b0 == 0xFF && b1 == 0xFE;
    if (big_endian || little_endian) {
      if (was_utf16) *was_utf16 = true;
      std::string text;
      text.reserve(bytes.size() / 2);
      for (size_t i = 2; i + 1 < bytes.size(); i += 2) {
        const unsigned hi = static_cast<unsigned char>(bytes[big_endian ? i : i + 1]);
        const unsigned lo = static_cast<unsigned char>(bytes[big_endian ? i + 1 : i]);
        const unsigned code = (hi << 8) | lo;
        text.push_back(code < 0x80 ? static_cast<char>(code) : '?');
      }
      return text;
    }
  }
  return bytes;
}

TextReader::TextReader(std::string path, std::string_view text)
    : path_(std::move(path)), text_(text) {}

bool TextReader::NextLine(std::string_view* line) {
  if (offset_ >= text_.size()) return false;
  size_t end = text_.find_first_of("\r\n", offset_);
  if (end == std::string_view::npos) end = text_.size();
  ++line_number_;
  if (end - offset_ > kMaxLineBytes) {
    Fail("line is longer than 1 MiB: this is binary data or a broken file",
         "check that the file is a text mesh of the format its extension says");
  }
  *line = text_.substr(offset_, end - offset_);
  if (line->find('\0') != std::string_view::npos) {
    Fail("line holds binary data (a NUL byte)",
         "check that the file is a text mesh of the format its extension says");
  }
  offset_ = end;
  if (offset_ < text_.size() && text_[offset_] == '\r') ++offset_;
  if (offset_ < text_.size() && text_[offset_] == '\n') ++offset_;
  return true;
}

void TextReader::SkipTo(size_t offset) {
  if (offset > text_.size()) offset = text_.size();
  for (size_t i = offset_; i < offset; ++i) {
    if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n'))) {
      ++line_number_;
    }
  }
  if (offset > offset_) offset_ = offset;
}

bool TextReader::NextTokens(char comment, std::vector<std::string_view>* tokens) {
  std::string_view line;
  while (NextLine(&line)) {
    SplitTokens(line, comment, tokens);
    if (!tokens->empty()) return true;
  }
  tokens->clear();
  return false;
}

std::string TextReader::Location() const { return "line " + std::to_string(line_number_); }

void TextReader::Fail(const std::string& what, const std::string& fix) const {
  throw InputError(path_, Location(), what, fix);
}

bool TokenStream::Next(std::string_view* token) {
  while (next_ >= tokens_.size()) {
    if (!reader_->NextTokens(comment_, &tokens_)) return false;
    next_ = 0;
  }
  *token = tokens_[next_++];
  return true;
}

void SplitTokens(std::string_view line, char comment, std::vector<std::string_view>* tokens) {
  tokens->clear();
  if (comment != '\0') {
    const size_t hash = line.find(comment);
    if (hash != std::string_view::npos) line = line.substr(0, hash);
  }
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && IsSpace(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !IsSpace(line[i])) ++i;
    if (i > start) tokens->push_back(line.substr(start, i - start));
  }
}

bool ParseDouble(std::string_view token, double* value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || token[0] == '+') return false;
  const char* end = token.data() + token.size();
  const std::from_chars_result result = std::from_chars(token.data(), end, *value);
  // A well-formed number too large or too small for a double: strtod rounds it to
  // +-HUGE_VAL (which the caller reports as infinite) or towards zero.
  if (result.ec == std::errc::result_out_of_range && result.ptr == end) {
    *value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return result.ec == std::errc() && result.ptr == end;
}

bool ParseInt64(std::string_view token, int64_t* value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || token[0] == '+') return false;
  const char* end = token.data() + token.size();
  const std::from_chars_result result = std::from_chars(token.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string ToLower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

std::string Counted(int64_t count, std::string_view one, std::string_view many) {
  return std::to_string(count) + " " + std::string(count == 1 ? one : many);
}

std::string Quote(std::string_view token) {
  std::string quoted = "'";
  const size_t shown = token.size() < 40 ? token.size() : 40;
  for (size_t i = 0; i < shown; ++i) {
    const unsigned char c = token[i];
    if (c >= 0x20 && c < 0x7F) {
      quoted.push_back(static_cast<char>(c));
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      quoted += hex;
    }
  }
  if (shown < token.size()) quoted += "...";
  return quoted + "'";
}

}  // namespace ergo
