// Bounded access to a mesh file held in memory: the whole file is loaded once (its size
// checked), text is split into lines (LF, CRLF or CR; a UTF-8 byte-order mark skipped,
// UTF-16 decoded) and lines into whitespace-separated tokens. Every failure is an InputError
// that names the file and the line, so readers never crash or loop on malformed input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ergo {

// Longest record of a fixed size (a header line, a vertex, a tetrahedron, a gmsh element):
// longer means binary data or a broken file. Records whose length grows with the mesh
// (polygon faces) may be as long as the file: lines are views into the loaded file and are
// read token by token (LineTokens, TokenStream), so they cost no memory beyond the mesh they
// describe; only token lists (NextTokens, 16 bytes per token) are bounded by this.
inline constexpr size_t kMaxRecordBytes = size_t{1} << 20;

// The bytes of `path`. Throws InputError when the file is missing, not a regular file (a
// directory, a FIFO, a device, a socket: checked before reading, so nothing blocks),
// unreadable, empty, or larger than 2 GiB.
std::string ReadFileBytes(const std::string& path);

// Turns raw bytes into text: strips a UTF-8 byte-order mark and decodes UTF-16 (with a BOM)
// to ASCII, replacing non-ASCII characters by '?'. Sets *was_utf16 when it decoded.
std::string BytesToText(std::string bytes, bool* was_utf16 = nullptr);

// Walks the lines of a text held elsewhere (the text must outlive the reader).
class TextReader {
 public:
  TextReader(std::string path, std::string_view text);

  // The next line without its terminator, of any length; false at the end of the text.
  // Throws InputError for a line holding a NUL byte.
  bool NextLine(std::string_view* line);

  // Throws InputError naming the line last returned when `line` (that line, or a part of it)
  // is longer than kMaxRecordBytes: for records of a fixed size.
  void RequireRecordLength(std::string_view line) const;

  // The next line that has at least one token once `comment` and what follows it are
  // removed; its tokens go to *tokens. False at the end of the text. For records of a
  // fixed size: throws for a line longer than kMaxRecordBytes.
  bool NextTokens(char comment, std::vector<std::string_view>* tokens);

  // 1-based number of the line last returned (0 before the first).
  int line_number() const { return line_number_; }
  // Byte offset of the first byte not yet returned, and the bytes from there to the end.
  size_t offset() const { return offset_; }
  size_t remaining_bytes() const { return text_.size() - offset_; }
  // Continues reading at `offset` (for formats that mix binary blocks into text); line
  // numbers are not updated.
  void Seek(size_t offset) { offset_ = offset < text_.size() ? offset : text_.size(); }
  // Continues reading at `offset` >= offset(), counting the lines passed over.
  void SkipTo(size_t offset);
  const std::string& path() const { return path_; }
  std::string_view text() const { return text_; }

  // "line N" for the line last returned.
  std::string Location() const;
  // Throws InputError(path, "line N", what, fix).
  [[noreturn]] void Fail(const std::string& what, const std::string& fix) const;

 private:
  std::string path_;
  std::string_view text_;
  size_t offset_ = 0;
  int line_number_ = 0;
};

// The whitespace-separated tokens of one line, one at a time: no list is built, so a line of
// any length costs nothing.
class LineTokens {
 public:
  LineTokens() = default;
  // Everything from the first `comment` character on is dropped (no comment when '\0').
  LineTokens(std::string_view line, char comment);

  // The next token; false when the line has none left.
  bool Next(std::string_view* token);
  // True when the line has no token left.
  bool AtEnd() const;
  // Bytes of the line after the last token returned.
  size_t remaining_bytes() const { return rest_.size(); }

 private:
  std::string_view rest_;
};

// Tokens across line breaks, for formats whose records may wrap (OFF faces, ASCII STL).
class TokenStream {
 public:
  TokenStream(TextReader* reader, char comment) : reader_(reader), comment_(comment) {}

  // The next token, reading further lines as needed; false at the end of the text.
  bool Next(std::string_view* token);
  // Forgets the rest of the current line (e.g. colours after an OFF face's indices).
  void SkipRestOfLine() { line_ = LineTokens(); }
  // True when the current line has no tokens left.
  bool AtLineEnd() const { return line_.AtEnd(); }
  // Bytes after the last token returned: the rest of its line and the lines that follow
  // (without that line's terminator).
  uint64_t remaining_bytes() const { return line_.remaining_bytes() + reader_->remaining_bytes(); }
  TextReader& reader() { return *reader_; }

 private:
  TextReader* reader_;
  char comment_;
  LineTokens line_;
};

// Splits `line` at spaces, tabs and other ASCII whitespace; drops everything from the
// first `comment` character on (no comment when it is '\0').
void SplitTokens(std::string_view line, char comment, std::vector<std::string_view>* tokens);

// Parses the whole token as a decimal number (a leading '+' allowed; "nan" and "inf" parse,
// so the caller can name them). False for anything else, e.g. "3.1+e2" or "1,5".
bool ParseDouble(std::string_view token, double* value);

// Parses the whole token as a decimal integer (a leading '+' allowed). False otherwise,
// including overflow of int64.
bool ParseInt64(std::string_view token, int64_t* value);

// Lower-cases ASCII letters, for keywords that files spell in any case.
std::string ToLower(std::string_view text);

// "1 triangle has" or "3 triangles have": a count with the matching noun (and verb).
std::string Counted(int64_t count, std::string_view one, std::string_view many);

// A token quoted for a message, cut to 40 characters and with control bytes escaped.
std::string Quote(std::string_view token);

}  // namespace ergo
