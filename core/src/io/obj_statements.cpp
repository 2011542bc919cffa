#include "obj_statements.h"

#include <algorithm>
#include <array>

namespace holefill::io {
namespace {

// A backslash at the end of a line continues it on the next, unless it ends a comment.
bool continues(std::string_view line) {
  return !line.empty() && line.back() == '\\' && line.find('#') == std::string_view::npos;
}

// What the reader keeps (through tinyobjloader's callbacks); "fo" is the old spelling of "f".
constexpr std::array<std::string_view, 9> kKept = {"v",      "vt",     "vn", "f", "fo",
                                                   "usemtl", "mtllib", "g",  "o"};
constexpr std::array<std::string_view, 5> kElements = {"l", "p", "curv", "curv2", "surf"};

}  // namespace

std::streambuf::int_type ObjStatements::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (!next_statement()) return traits_type::eof();
  served_.assign(statement_);
  served_ += " \n";
  setg(served_.data(), served_.data(), served_.data() + served_.size());
  return traits_type::to_int_type(*gptr());
}

bool ObjStatements::next_statement() {
  std::string_view line;
  while (lines_.next(line)) {
    line_ = lines_.number();
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
    std::string_view rest = line.substr(0, line.find('#'));  // comments run to the line's end
    statement_ = rest;
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    classify(keyword);
    std::string_view corners = rest;
    if ((keyword == "f" || keyword == "fo") && take_token(corners).empty()) ++empty_faces_;
    if (keyword == "fo") {                     // served as "f" so that tinyobjloader sees a face
      std::string face(rest.size() + 1, 'f');  // `rest` may lie in joined_: built apart first
      std::copy(rest.begin(), rest.end(), face.begin() + 1);
      joined_ = std::move(face);
      statement_ = joined_;
    }
    return true;
  }
  return false;
}

void ObjStatements::classify(std::string_view keyword) {
  for (const auto kept : kKept) {
    if (keyword == kept) return;
  }
  for (const auto element : kElements) {
    if (keyword == element) {
      ++elements_ignored_;
      return;
    }
  }
  ++not_kept_[std::string(keyword)];
}

}  // namespace holefill::io
