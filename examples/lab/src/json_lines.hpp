// Internal: maps field paths ("camera.fov", "opaque[1].texture") of a JSON
// text to the line where the value starts, so schema errors can cite lines.
// Accepts what nlohmann::json accepts with comments enabled.
#pragma once
#include <map>
#include <string>

namespace snell::lab::detail {

class JsonLines {
 public:
  explicit JsonLines(const std::string& text);
  // 0 when the path is unknown.
  int line(const std::string& path) const;
  // The first key given twice in one object (nlohmann::json keeps the last one silently): its path, the line
  // of its first and of its second occurrence; an empty path when every key is given once.
  struct Duplicate {
    std::string path;
    int firstLine = 0, secondLine = 0;
  };
  const Duplicate& duplicate() const { return duplicate_; }

 private:
  static constexpr int kMaxDepth = 256;
  std::map<std::string, int> lines_;
  Duplicate duplicate_;
  const std::string& text_;
  std::size_t pos_ = 0;
  int lineNo_ = 1;

  void skipSpace();
  void value(const std::string& path, int depth);
  void skipValue();
  std::string stringToken();
  void advance();
};

}  // namespace snell::lab::detail
