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
constexpr std::array<std::string_view, 10> kKept = {"v",      "vt",     "vn", "f", "fo",
                                                    "usemtl", "mtllib", "g",  "o", "s"};
constexpr std::array<std::string_view, 5> kElements = {"l", "p", "curv", "curv2", "surf"};

}  // namespace

std::streambuf::int_type ObjStatements::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  bool served = false;
  while (!served && !failure_ && next_statement()) {
    const std::string_view keyword = read_directly_ ? direct_keyword() : std::string_view();
    if (keyword.empty()) {
      served = true;
      continue;
    }
    // std::istream would swallow an exception thrown here: kept for rethrow_failure().
    try {
      read_directly_(keyword);
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
    keyword_ = keyword;
    arguments_ = rest;
    if (keyword == "f" || keyword == "fo") {
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

std::string_view ObjStatements::direct_keyword() const {
  // tinyobjloader splits the keyword off at spaces and tabs only.
  auto space_or_tab = [](char c) { return c == ' ' || c == '\t'; };
  const std::string_view before = statement_.substr(0, keyword_.data() - statement_.data());
  if (!std::all_of(before.begin(), before.end(), space_or_tab)) return {};
  if (!arguments_.empty() && !space_or_tab(arguments_.front())) return {};
  if (keyword_ == "v" || keyword_ == "vt" || keyword_ == "vn" || keyword_ == "s") return keyword_;
  // tinyobjloader reports a face only when something follows its keyword.
  if (keyword_ == "f" && arguments_.find_first_not_of(" \t") != std::string_view::npos) {
    return keyword_;
  }
  return {};
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
