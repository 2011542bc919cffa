#include "obj_statements.h"

#include <algorithm>

namespace holefill::io {
namespace {

// A backslash at the end of a line continues it on the next, unless it ends a comment.
bool continues(std::string_view line) {
  return !line.empty() && line.back() == '\\' && line.find('#') == std::string_view::npos;
}

// What a keyword is to the reader: one it reads directly, one that tinyobjloader reads for it
// (usemtl, mtllib, g, o), an element it ignores (l, p, curv, curv2, surf), or another.
enum class KeywordKind { Direct, Named, Element, Other };

// One switch on the keyword's length and first letter, then at most two comparisons: this runs
// for every statement (ten string comparisons did before).
KeywordKind kind_of(std::string_view keyword, DirectStatement& direct) {
  auto is = [&](std::string_view word, DirectStatement kind) {
    direct = kind;
    return keyword == word;
  };
  switch (keyword.size()) {
    case 1:
      if (is("v", DirectStatement::Vertex) || is("f", DirectStatement::Face) ||
          is("s", DirectStatement::Smoothing)) {
        return KeywordKind::Direct;
      }
      if (keyword == "g" || keyword == "o") return KeywordKind::Named;
      if (keyword == "l" || keyword == "p") return KeywordKind::Element;
      return KeywordKind::Other;
    case 2:
      // "fo" is the old spelling of "f".
      if (is("vt", DirectStatement::Texcoord) || is("vn", DirectStatement::Normal) ||
          is("fo", DirectStatement::Face)) {
        return KeywordKind::Direct;
      }
      return KeywordKind::Other;
    case 4:
      return keyword == "curv" || keyword == "surf" ? KeywordKind::Element : KeywordKind::Other;
    case 5:
      return keyword == "curv2" ? KeywordKind::Element : KeywordKind::Other;
    case 6:
      return keyword == "usemtl" || keyword == "mtllib" ? KeywordKind::Named : KeywordKind::Other;
    default:
      return KeywordKind::Other;
  }
}

}  // namespace

std::streambuf::int_type ObjStatements::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  bool served = false;
  while (!served && !failure_ && next_statement()) {
    DirectStatement kind;
    if (!read_directly_ || !is_direct(kind)) {
      served = true;
      continue;
    }
    // std::istream would swallow an exception thrown here: kept for rethrow_failure().
    try {
      read_directly_(kind);
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  if (!served) return traits_type::eof();
  served_.assign(statement_);
  served_ += " \n";
  setg(served_.data(), served_.data(), served_.data() + served_.size());
  return traits_type::to_int_type(*gptr());
}

bool ObjStatements::next_statement() {
  std::string_view line;
  while (lines_.next(line)) {
    line_ = lines_before_ + lines_.number();
    if (continues(line)) {
      joined_.assign(line.substr(0, line.size() - 1));
      std::string_view more;
      bool continued = true;
      while (continued && lines_.next(more)) {
        continued = continues(more);
        joined_ += ' ';
        joined_ += more.substr(0, more.size() - (continued ? 1 : 0));
      }
      line = joined_;
    }
    std::string_view rest = line.substr(0, comment_start(line));  // comments run to the end
    statement_ = rest;
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    const KeywordKind kind = kind_of(keyword, direct_kind_);
    keyword_is_direct_ = kind == KeywordKind::Direct;
    if (kind == KeywordKind::Element) ++elements_ignored_;
    if (kind == KeywordKind::Other) ++not_kept_[std::string(keyword)];
    keyword_ = keyword;
    arguments_ = rest;
    if (keyword_is_direct_ && direct_kind_ == DirectStatement::Face) {
      std::string_view corners = rest;
      skip_blanks(corners);
      if (corners.empty()) ++empty_faces_;
    }
    if (keyword == "fo") {                     // served as "f" so that tinyobjloader sees a face
      std::string face(rest.size() + 1, 'f');  // `rest` may lie in joined_: built apart first
      std::copy(rest.begin(), rest.end(), face.begin() + 1);
      joined_ = std::move(face);
      statement_ = joined_;
      keyword_ = statement_.substr(0, 1);
      arguments_ = statement_.substr(1);
    }
    return true;
  }
  return false;
}

std::size_t ObjStatements::comment_start(std::string_view line) {
  if (line.data() < text_.data() || line.data() >= text_.data() + text_.size()) {
    return line.find('#');  // a continued statement, joined
  }
  const auto start = static_cast<std::size_t>(line.data() - text_.data());
  const std::size_t hash = next_hash_.at_or_after(start);
  return hash - start < line.size() ? hash - start : std::string_view::npos;
}

bool ObjStatements::is_direct(DirectStatement& kind) const {
  if (!keyword_is_direct_) return false;
  // tinyobjloader splits the keyword off at spaces and tabs only.
  auto space_or_tab = [](char c) { return c == ' ' || c == '\t'; };
  if (keyword_.data() != statement_.data()) {
    const std::string_view before = statement_.substr(0, keyword_.data() - statement_.data());
    if (!std::all_of(before.begin(), before.end(), space_or_tab)) return false;
  }
  if (!arguments_.empty() && !space_or_tab(arguments_.front())) return false;
  kind = direct_kind_;
  // tinyobjloader reports a face only when something follows its keyword.
  return kind != DirectStatement::Face ||
         arguments_.find_first_not_of(" \t") != std::string_view::npos;
}

}  // namespace holefill::io
