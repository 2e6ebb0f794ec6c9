#include "json_lines.hpp"

#include <cstdlib>
#include <string_view>

namespace snell::lab::detail {

JsonLines::JsonLines(const std::string& text) : text_(text) {
  skipSpace();
  if (pos_ < text_.size()) value("", 0);
}

int JsonLines::line(const std::string& path) const {
  const auto it = lines_.find(path);
  return it == lines_.end() ? 0 : it->second;
}

void JsonLines::advance() {
  if (pos_ < text_.size() && text_[pos_] == '\n') ++lineNo_;
  ++pos_;
}

void JsonLines::skipSpace() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      advance();
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
      while (pos_ < text_.size() && text_[pos_] != '\n') advance();
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
      advance();
      advance();
      while (pos_ + 1 < text_.size() && !(text_[pos_] == '*' && text_[pos_ + 1] == '/')) advance();
      advance();
      advance();
    } else {
      break;
    }
  }
}

std::string JsonLines::stringToken() {
  std::string s;
  advance();  // opening quote
  while (pos_ < text_.size() && text_[pos_] != '"') {
    if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
      advance();
      const char e = text_[pos_];
      if (e == 'u' && pos_ + 4 < text_.size()) {
        // \uXXXX: an ASCII code point is that character (so "\u006Fbject" is the key object, as the JSON
        // parser reads it); any other is kept raw (no schema key uses one).
        const std::string hex = text_.substr(pos_ + 1, 4);
        char* end = nullptr;
        const long code = std::strtol(hex.c_str(), &end, 16);
        if (end == hex.c_str() + 4 && code > 0 && code < 0x80) {
          for (int i = 0; i < 4; ++i) advance();
          s += static_cast<char>(code);
        } else {
          s += e;
        }
      } else {
        s += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      }
    } else {
      s += text_[pos_];
    }
    advance();
  }
  advance();  // closing quote
  return s;
}

// Values nested deeper than kMaxDepth get no line of their own (their
// fields are reported at the line of the deepest recorded ancestor): they are
// skipped in one iterative pass, so neither the stack nor the map grows with
// the nesting. Returning without consuming them made the enclosing array's
// loop spin forever on a scene nested 258 arrays deep.
void JsonLines::skipValue() {
  constexpr std::string_view kDelimiters = ",:[]{}\"/ \t\r\n";
  int nesting = 0;
  do {
    skipSpace();
    if (pos_ >= text_.size()) return;
    const char c = text_[pos_];
    if (c == '"') {
      stringToken();
    } else if (c == '[' || c == '{') {
      ++nesting;
      advance();
    } else if (c == ']' || c == '}') {
      if (nesting == 0) return;  // the end of the enclosing value, not ours
      --nesting;
      advance();
    } else if (c == ',' || c == ':') {
      advance();
    } else {
      advance();  // a scalar: at least one character (so this loop always progresses), up to a delimiter
      while (pos_ < text_.size() && kDelimiters.find(text_[pos_]) == std::string_view::npos) advance();
    }
  } while (nesting > 0);
}

void JsonLines::value(const std::string& path, int depth) {
  if (pos_ >= text_.size()) return;
  if (depth > kMaxDepth) {
    skipValue();
    return;
  }
  // A path is recorded once; only a key repeated in one object reaches an existing one (array elements
  // carry their index).
  const auto inserted = lines_.emplace(path, lineNo_);
  if (!inserted.second && duplicate_.path.empty()) duplicate_ = {path, inserted.first->second, lineNo_};
  const char c = text_[pos_];
  if (c == '{') {
    advance();
    while (true) {
      skipSpace();
      if (pos_ >= text_.size()) return;
      if (text_[pos_] == '}') {
        advance();
        return;
      }
      if (text_[pos_] == ',') {
        advance();
        continue;
      }
      if (text_[pos_] != '"') return;  // not JSON we understand: stop quietly
      const std::string key = stringToken();
      skipSpace();
      if (pos_ < text_.size() && text_[pos_] == ':') advance();
      skipSpace();
      value(path.empty() ? key : path + "." + key, depth + 1);
    }
  } else if (c == '[') {
    advance();
    int index = 0;
    while (true) {
      skipSpace();
      if (pos_ >= text_.size()) return;
      if (text_[pos_] == ']') {
        advance();
        return;
      }
      if (text_[pos_] == ',') {
        advance();
        continue;
      }
      const std::size_t before = pos_;
      value(path + "[" + std::to_string(index++) + "]", depth + 1);
      if (pos_ == before) return;  // not JSON we understand: stop quietly
    }
  } else if (c == '"') {
    stringToken();
  } else {
    while (pos_ < text_.size()) {
      const char d = text_[pos_];
      if (d == ',' || d == '}' || d == ']' || d == ' ' || d == '\t' || d == '\r' || d == '\n' || d == '/') break;
      advance();
    }
  }
}

}  // namespace snell::lab::detail
