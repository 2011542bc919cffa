// Reading an OBJ's statements into a Soup (obj_reader.cpp says who reads what), one part of the
// text at a time: the whole text, or (a big file, on two threads) its first half here and its
// second half into a second, detached reading that knows nothing of the first half and is
// appended to this one afterwards. A detached reading defers what needs the first half: its
// relative indices are recorded to be resolved when appended, its faces start with the material,
// group, object and smoothing group the first half ends with, and its lines count from its own
// start. Where that cannot give what one reading would (a relative index that reaches before the
// file's first element, any error), the second half is read again after the first instead, so
// the soup, the warnings and every message are the one-thread reading's.
#pragma once

#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "holefill/io.h"
#include "huge_pages.h"
#include "obj_estimate.h"
#include "obj_statements.h"
#include "soup.h"
#include "two_parts.h"

namespace holefill::io {

// Indices are kept as the soup keeps them, ints, parsed straight into it (as long longs they
// were 8 bytes a corner and kind, 72 MB for a 1M-triangle file, copied at the end). A face may
// refer ahead to any number, which the end of the reading refuses, quoting it: a number that
// does not fit an int is kept as kBeyond, and the first such by corner aside.
inline constexpr int kBeyond = std::numeric_limits<int>::max();

// One value per corner of one kind: vertex indices (from 0), or texture coordinate or normal
// numbers (from 1, 0 for none; the column stays empty until a corner has one).
class CornerColumn {
 public:
  CornerColumn(std::vector<int>& values, int base) : values_(values), base_(base) {}
  CornerColumn(const CornerColumn&) = delete;
  CornerColumn& operator=(const CornerColumn&) = delete;

  // Corner `corner` (the column's next or, while it is empty, any later one) refers to element
  // `index` (from 0; below 0 only when `relative`, reaching before a detached part); the
  // corners before it that were not given one have none. `relative`: recorded, so that the
  // elements before the part can be added when it is appended.
  void push(std::size_t corner, long long index, bool relative) {
    const long long value = index + base_;
    if (values_.size() == corner && !relative && value < kBeyond) [[likely]] {
      values_.push_back(static_cast<int>(value));
      return;
    }
    push_other(corner, index, relative);
  }
  // The next corner has none (nothing is stored while no corner has one).
  void push_none() {
    if (!values_.empty()) values_.push_back(0);
  }
  // Forgets the corners from `corner` on.
  void truncate(std::size_t corner) {
    if (values_.size() > corner) values_.resize(corner);
    forget_from(corner);
  }
  // Gives the corners from `corner` on none.
  void clear_from(std::size_t corner);
  // The element (from 0) that corner c refers to; c has one.
  long long index(std::size_t c) const {
    return values_[c] == kBeyond ? beyond_index_ : static_cast<long long>(values_[c]) - base_;
  }
  // Whether no corner refers to an element past the first `defined` ones (one pass, where
  // finding the first that does takes a pass over the faces).
  bool within(std::size_t defined) const;
  // Whether corner c refers to an element past the first `defined` ones.
  bool beyond(std::size_t c, std::size_t defined) const {
    const int value = values_[c];
    return value - base_ >= static_cast<long long>(defined) && (base_ == 0 || value != 0);
  }
  // Whether every relative index recorded, with `before` elements added, is one of the file's.
  bool relative_reach(std::size_t before) const;
  // Appends `later`'s corners (a detached part's, `corners` of them; its relative indices
  // resolved with `before` more elements) after this column's `own` corners.
  void append(CornerColumn& later, std::size_t own, std::size_t corners, std::size_t before);
  std::vector<int>& values() { return values_; }
  const std::vector<int>& values() const { return values_; }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  // push() where the corners before are not all given, the index is relative or too big.
  void push_other(std::size_t corner, long long index, bool relative);
  void forget_from(std::size_t corner) {
    while (!relative_.empty() && relative_.back() >= corner) relative_.pop_back();
    if (beyond_corner_ >= corner && beyond_corner_ != kNone) beyond_corner_ = kNone;
  }
  std::vector<int>& values_;
  int base_;
  std::vector<std::size_t> relative_;  // corners with a relative index (a detached part's only)
  std::size_t beyond_corner_ = kNone;
  long long beyond_index_ = 0;
};

struct ObjIndexKind;

class ObjReading {
 public:
  // `detached`: the second part of a file, read without the first (see above).
  ObjReading(const std::filesystem::path& path, bool detached);
  ObjReading(const ObjReading&) = delete;
  ObjReading& operator=(const ObjReading&) = delete;

  // Gives the soup's arrays room for `counts` elements (see obj_estimate.h), on huge pages
  // (huge_pages.h: a fault per 4 KB page was a large part of reading a big file), before
  // anything is read; a reading that is not detached gives its positions the mesh's room as well
  // (the mesh then takes them without a copy).
  void reserve(const ObjCounts& counts);
  // Reads the statements of `text` (whole lines), which follows what was read so far. Throws
  // FileError or InvalidMeshError naming the line at the first bad statement.
  void read(std::string_view text);
  // Appends `second` (a detached reading of the text after this one's); false, with nothing
  // changed, when it cannot give what reading its text here would (then read it here).
  bool append(ObjReading& second);
  // Checks the indices against what the file defines, adds the warnings and returns the soup.
  Soup finish(LoadReport& report);

  // Called for the statements tinyobjloader reads (usemtl, g, o, mtllib).
  void use_material(std::string_view name);
  void set_group(std::string_view names);
  void set_object(std::string_view name);
  void add_material_library(const std::filesystem::path& file);

 private:
  // One of the per-face names (material, group, object, smoothing group): the table of the
  // names in the order they first came, their numbers (from 1), and the current one (0: none;
  // kInherited in a detached part until its first statement: what the first part ends with).
  struct FaceNames {
    std::vector<std::string>& names;
    std::vector<int>& faces;
    std::unordered_map<std::string, int> numbers = {};
    int initial = 0;  // what faces have before the first name: 0, or kInherited
    int current = initial;
    // The number of `name`, added at the end when new.
    int number(std::string_view name);
    // Gives the faces read from now on `name`.
    void set(std::string_view name) { current = number(name); }
    // Records `current` for face `face` (values stay empty while every face has the initial),
    // giving the values room for `room` faces when they start.
    void give(std::size_t face, std::size_t room) {
      if (current == initial && faces.empty()) return;
      if (faces.empty()) reserve_on_huge_pages(faces, room);
      if (faces.size() < face) faces.resize(face, initial);
      faces.push_back(current);
    }
    // Appends `later`'s faces (a detached part's, `count` of them) after this one's `own`,
    // giving the values room for `room` faces when they start.
    void append(const FaceNames& later, std::size_t own, std::size_t count, std::size_t room);
  };
  static constexpr int kInherited = -1;

  void read_statement(DirectStatement kind);
  void read_vertex();
  void read_vertex_colour(std::string_view rest);
  void read_texcoord();
  void read_normal();
  void read_face();
  void read_smoothing_group();
  // The statement's numbers after its keyword, at most `most`; refuses a missing or bad one
  // among the first `least`, and non-finite ones.
  int read_numbers(double* values, int least, int most, const char* what) const;
  long long read_index(std::string_view text, std::string_view corner, std::size_t defined,
                       const ObjIndexKind& kind) const;
  // A read index's 0-based value; refuses 0 and relative indices before the first element
  // (before the part's, in a detached part: those are checked when it is appended).
  long long resolve_index(long long index, std::size_t defined, const ObjIndexKind& kind) const {
    return index > 0 ? index - 1 : resolve_other_index(index, defined, kind);
  }
  long long resolve_other_index(long long index, std::size_t defined,
                                const ObjIndexKind& kind) const;
  struct CornerCounts;
  // A face's corners, pushed onto the soup's corners and the texture coordinate and normal
  // columns; read_plain_corners reads the usual ones in place and returns false (some corners
  // pushed) at the first that is not one, then read_corners tells what is wrong with it.
  void read_corners(std::string_view rest, CornerCounts& given);
  bool read_plain_corners(std::string_view rest, CornerCounts& given);
  // One corner, its indices as written (0: not given) and resolved.
  void push_corner(const long long* written, const long long* resolved);
  void check_indices(const CornerColumn& column, std::size_t defined,
                     const ObjIndexKind& kind) const;
  [[noreturn]] void fail_here(const std::string& reason) const;

  Soup soup_;
  const std::filesystem::path& path_;
  const bool detached_;
  const ObjStatements* statements_ = nullptr;  // the statements being read
  std::size_t lines_ = 0;                      // lines read before them
  // The soup's corners, texture coordinate and normal numbers by corner, checked against the
  // counts at the end (a face may refer ahead).
  CornerColumn vertex_{soup_.corners, 0}, texcoord_{soup_.corner_texcoord, 1},
      normal_{soup_.corner_normal, 1};
  bool any_texcoord_ = false, any_normal_ = false;
  std::size_t partial_texcoords_ = 0, partial_normals_ = 0;  // faces with some corners only
  FaceNames material_{soup_.obj.materials, soup_.face_material},
      group_{soup_.obj.groups, soup_.face_group}, object_{soup_.obj.objects, soup_.face_object},
      smoothing_{soup_.obj.smoothing_groups, soup_.face_smoothing};
  // What ObjStatements counts, over the parts read.
  std::size_t elements_ignored_ = 0, empty_faces_ = 0;
  std::map<std::string, std::size_t> not_kept_;
};

}  // namespace holefill::io
