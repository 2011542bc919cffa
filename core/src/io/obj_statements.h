// The statements of an OBJ text, served to tinyobjloader one at a time through a std::streambuf:
// each logical line (a backslash at a line's end continues it; '#' starts a comment) with its
// comment removed, then " \n" (a keyword alone, "g", is then followed by a blank, as
// tinyobjloader needs). While tinyobjloader handles a statement (and calls back), the
// stream knows which one it is, so the callbacks can read its numbers again exactly and name its
// line. Statements holefill does not keep are counted here, since tinyobjloader's callbacks
// never see them. The statements whose numbers are all the reader wants (v, vt, vn, f) can be
// handed to the reader directly instead (read_directly): tinyobjloader's own pass over them was
// a third of reading a big OBJ, for numbers that were read again anyway; so can smoothing groups
// (s), which tinyobjloader's callbacks do not report.
#pragma once

#include <exception>
#include <functional>
#include <map>
#include <streambuf>
#include <string>
#include <string_view>

#include "text_scan.h"

namespace holefill::io {

// The statements that ObjStatements can hand to the reader directly (read_directly).
enum class DirectStatement { Vertex, Texcoord, Normal, Face, Smoothing };

class ObjStatements : public std::streambuf {
 public:
  // `text` follows `lines_before` lines of the file (its first line is line lines_before + 1).
  explicit ObjStatements(std::string_view text, std::size_t lines_before = 0)
      : text_(text), lines_(text), next_hash_(text, '#'), lines_before_(lines_before) {}

  // The statement being read (no comment, no end of line) and the line it starts on.
  std::string_view statement() const { return statement_; }
  // The statement after its keyword (what take_token leaves of it; "fo" counts as "f").
  std::string_view arguments() const { return arguments_; }
  std::size_t line() const { return line_; }
  // The lines of the text read so far (all of them once the stream has ended).
  std::size_t lines_read() const { return lines_.number(); }

  // Lines, points, curves and surfaces (not surfaces holefill fills), and the keywords of other
  // statements that are not kept (free-form attributes "vp", "deg", ...), by count.
  std::size_t elements_ignored() const { return elements_ignored_; }
  const std::map<std::string, std::size_t>& not_kept() const { return not_kept_; }
  // Faces with no corners (tinyobjloader skips them).
  std::size_t empty_faces() const { return empty_faces_; }

  // From now on each statement that tinyobjloader would take for a vertex ("v"), texture
  // coordinate ("vt"), normal ("vn") or face with corners ("f", "fo"), and each smoothing group
  // ("s"), goes to `read` with its kind ("fo" is a face), in the file's order among the served
  // ones, instead of being served.
  // What `read` throws ends the stream; rethrow_failure() throws it again.
  void read_directly(std::function<void(DirectStatement)> read) {
    read_directly_ = std::move(read);
  }
  // Throws what a direct read threw, if one did.
  void rethrow_failure() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 protected:
  int_type underflow() override;

 private:
  // Moves to the next statement that is not blank; false at the end of the text.
  bool next_statement();
  // Whether tinyobjloader would take the statement for one that read_directly covers (its
  // keyword after spaces and tabs only, followed by one or by the end), and which. Uses the
  // keyword next_statement found instead of scanning the statement again.
  bool is_direct(DirectStatement& kind) const;

  // Where a line's comment starts (npos: none).
  std::size_t comment_start(std::string_view line);

  std::string_view text_;
  Lines lines_;
  NextOccurrence next_hash_;
  std::size_t lines_before_;
  std::string joined_;  // a statement continued over several lines
  std::string served_;  // what tinyobjloader reads: the statement and '\n'
  std::string_view statement_;
  std::string_view keyword_, arguments_;  // parts of statement_
  bool keyword_is_direct_ = false;        // one of read_directly's, which is direct_kind_
  DirectStatement direct_kind_ = DirectStatement::Vertex;
  std::size_t line_ = 0;
  std::size_t elements_ignored_ = 0;
  std::size_t empty_faces_ = 0;
  std::map<std::string, std::size_t> not_kept_;
  std::function<void(DirectStatement)> read_directly_;
  std::exception_ptr failure_;
};

}  // namespace holefill::io
