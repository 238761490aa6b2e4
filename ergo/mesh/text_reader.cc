#include "ergo/mesh/text_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "ergo/mesh/input_error.h"

namespace ergo {

namespace {

constexpr uintmax_t kMaxFileBytes = uintmax_t{1} << 31;

// Closes a POSIX file descriptor when it goes out of scope.
struct FileCloser {
  int descriptor;
  ~FileCloser() { ::close(descriptor); }
};

// Throws unless `status` is that of a regular file, saying what the path is instead.
void RequireRegularFile(const std::string& path, const struct stat& status) {
  if (S_ISREG(status.st_mode)) return;
  if (S_ISDIR(status.st_mode)) {
    throw InputError(path, "", "this is a directory, not a mesh file", "pass a mesh file");
  }
  const bool stream = S_ISFIFO(status.st_mode) || S_ISSOCK(status.st_mode);
  const char* kind = S_ISFIFO(status.st_mode)   ? "a named pipe (FIFO)"
                     : S_ISSOCK(status.st_mode) ? "a socket"
                     : S_ISCHR(status.st_mode)  ? "a character device"
                     : S_ISBLK(status.st_mode)  ? "a block device"
                                                : "a special file";
  throw InputError(path, "",
                   std::string("this is ") + kind +
                       ", not a regular file: ergo reads a mesh file whole, so it must be a "
                       "file of known end",
                   stream ? "save what it delivers to a regular file first (e.g. cat " + path +
                                " > mesh.stl, with the mesh's extension) and pass that file"
                          : std::string("pass a regular mesh file"));
}

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || c == '\n';
}

}  // namespace

std::string ReadFileBytes(const std::string& path) {
  // Checked before opening, and again on the open descriptor (the path may change in
  // between): a FIFO would block the reader forever and a device would never end.
  struct stat status;
  if (::stat(path.c_str(), &status) != 0) {
    throw InputError(path, "", "the file does not exist or cannot be accessed",
                     "check the path and its permissions");
  }
  RequireRegularFile(path, status);
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0) {
    throw InputError(
        path, "",
        std::string("the file cannot be opened for reading (") + std::strerror(errno) + ")",
        "check its permissions");
  }
  const FileCloser closer{descriptor};
  if (::fstat(descriptor, &status) != 0) {
    throw InputError(path, "", "the file cannot be examined", "check the file");
  }
  RequireRegularFile(path, status);
  ::fcntl(descriptor, F_SETFL, ::fcntl(descriptor, F_GETFL) & ~O_NONBLOCK);
  // Read in chunks rather than trusting the size, which is 0 for /proc files; the size only
  // reserves memory.
  std::string bytes;
  if (status.st_size > 0 && static_cast<uintmax_t>(status.st_size) <= kMaxFileBytes) {
    bytes.reserve(static_cast<size_t>(status.st_size));
  }
  char chunk[1 << 16];
  while (true) {
    const ssize_t count = ::read(descriptor, chunk, sizeof chunk);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) {
      throw InputError(path, "",
                       std::string("a read error occurred (") + std::strerror(errno) + ")",
                       "check the disk and the file");
    }
    if (count == 0) break;
    bytes.append(chunk, static_cast<size_t>(count));
    if (bytes.size() > kMaxFileBytes) {
      throw InputError(path, "", "the file is larger than 2 GiB",
                       "split the mesh or decimate it; ergo reads meshes up to 2 GiB");
    }
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

void TextReader::RequireRecordLength(std::string_view line) const {
  if (line.size() > kMaxRecordBytes) {
    Fail("line is longer than 1 MiB: this is binary data or a broken file",
         "check that the file is a text mesh of the format its extension says");
  }
}

bool TextReader::NextTokens(char comment, std::vector<std::string_view>* tokens) {
  std::string_view line;
  while (NextLine(&line)) {
    RequireRecordLength(line);
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

LineTokens::LineTokens(std::string_view line, char comment) : rest_(line) {
  if (comment == '\0') return;
  const size_t start = rest_.find(comment);
  if (start != std::string_view::npos) rest_ = rest_.substr(0, start);
}

bool LineTokens::Next(std::string_view* token) {
  size_t start = 0;
  while (start < rest_.size() && IsSpace(rest_[start])) ++start;
  if (start == rest_.size()) {
    rest_ = {};
    return false;
  }
  size_t end = start;
  while (end < rest_.size() && !IsSpace(rest_[end])) ++end;
  *token = rest_.substr(start, end - start);
  rest_.remove_prefix(end);
  return true;
}

bool LineTokens::AtEnd() const {
  for (const char c : rest_) {
    if (!IsSpace(c)) return false;
  }
  return true;
}

bool TokenStream::Next(std::string_view* token) {
  while (!line_.Next(token)) {
    std::string_view line;
    if (!reader_->NextLine(&line)) return false;
    line_ = LineTokens(line, comment_);
  }
  return true;
}

void SplitTokens(std::string_view line, char comment, std::vector<std::string_view>* tokens) {
  tokens->clear();
  LineTokens cursor(line, comment);
  std::string_view token;
  while (cursor.Next(&token)) tokens->push_back(token);
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
