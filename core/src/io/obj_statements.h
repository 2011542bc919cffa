// The statements of an OBJ text, served to tinyobjloader one at a time through a std::streambuf:
// each logical line (a backslash at a line's end continues it; '#' starts a comment) with its
// comment removed, then " \n" (a keyword alone, "g", is then followed by a blank, as
// tinyobjloader needs). While tinyobjloader handles a statement (and calls back), the
// stream knows which one it is, so the callbacks can read its numbers again exactly and name its
// line. Statements holefill does not keep are counted here, since tinyobjloader's callbacks
// never see them.
#pragma once

#include <map>
#include <streambuf>
#include <string>
#include <string_view>

#include "text_scan.h"

namespace holefill::io {

class ObjStatements : public std::streambuf {
 public:
  explicit ObjStatements(std::string_view text) : lines_(text) {}

  // The statement being read (no comment, no end of line) and the line it starts on.
  std::string_view statement() const { return statement_; }
  std::size_t line() const { return line_; }

  // Lines, points, curves and surfaces (not surfaces holefill fills), and the keywords of other
  // statements that are not kept (smoothing groups "s", free-form attributes, ...), by count.
  std::size_t elements_ignored() const { return elements_ignored_; }
  const std::map<std::string, std::size_t>& not_kept() const { return not_kept_; }
  // Faces with no corners (tinyobjloader skips them).
  std::size_t empty_faces() const { return empty_faces_; }

 protected:
  int_type underflow() override;

 private:
  // Moves to the next statement that is not blank; false at the end of the text.
  bool next_statement();
  void classify(std::string_view keyword);

  Lines lines_;
  std::string joined_;  // a statement continued over several lines
  std::string served_;  // what tinyobjloader reads: the statement and '\n'
  std::string_view statement_;
  std::size_t line_ = 0;
  std::size_t elements_ignored_ = 0;
  std::size_t empty_faces_ = 0;
  std::map<std::string, std::size_t> not_kept_;
};

}  // namespace holefill::io
