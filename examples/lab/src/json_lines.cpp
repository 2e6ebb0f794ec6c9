#include "json_lines.hpp"

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
      s += e == 'n' ? '\n' : e == 't' ? '\t' : e;  // \uXXXX kept raw: keys are ASCII
    } else {
      s += text_[pos_];
    }
    advance();
  }
  advance();  // closing quote
  return s;
}

void JsonLines::value(const std::string& path, int depth) {
  if (depth > 256 || pos_ >= text_.size()) return;
  lines_.emplace(path, lineNo_);
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
      value(path + "[" + std::to_string(index++) + "]", depth + 1);
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
