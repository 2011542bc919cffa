// Reading a big text file in two parts, the second on a thread of its own (OBJ, OFF, ASCII PLY).
// The second part is read alone into a part of its own, with what it needs to know of the
// first (where it starts: the line and record numbers before it); the reader appends it to the
// first, or, where it could not be read alone (any error, anything that depends on the first
// part), reads it again after the first, so that the soup, the warnings and every message are
// the one-thread reading's.
#pragma once

#include <cstring>
#include <string_view>
#include <vector>

#include "soup.h"
#include "two_threads.h"

namespace holefill::io {

// From this size on, a text file's two parts are read on two threads (below, a thread costs more
// than it saves, and small files stay on one).
inline constexpr std::size_t kTwoPartsFrom = std::size_t{8} << 20;

// Where a reader that cuts `text` at a line boundary near `near` does (the start of the line
// after the first LF at or after `near`), or text.size() when there is none.
inline std::size_t line_start_after(std::string_view text, std::size_t near) {
  if (near >= text.size()) return text.size();
  const void* found = std::memchr(text.data() + near, '\n', text.size() - near);
  return found ? static_cast<std::size_t>(static_cast<const char*>(found) - text.data()) + 1
               : text.size();
}

// Runs `read_second` on a thread of its own (run_both; here after read_first when no thread can
// be had) and `read_first` here. What read_first throws is thrown (once the thread is done); what
// read_second throws is dropped, as the part is read again after the first. Returns whether
// read_second finished.
template <class ReadFirst, class ReadSecond>
bool read_in_two_parts(ReadFirst&& read_first, ReadSecond&& read_second) {
  bool second_read = false;
  run_both(true, read_first, [&] {
    try {
      read_second();
      second_read = true;
    } catch (...) {  // read again after the first, where the first part's errors come first
    }
  });
  return second_read;
}

// Moves `from`'s elements to the end of `to`, and frees `from` (a part's arrays are freed as they
// are appended, so that two copies of each are not held at once).
template <class T>
void append_and_free(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
  std::vector<T>().swap(from);
}

// Appends the positions and faces `later` read of a second part to `soup`, freeing them there:
// its corners index the whole file's vertices and its faces' lines count the whole file's lines
// (OFF, PLY), so only the face ends move. Attribute columns are the caller's.
inline void append_positions_and_faces(Soup& soup, Soup& later) {
  append_and_free(soup.positions, later.positions);
  const std::size_t corners = soup.corners.size(), faces = soup.face_count();
  append_and_free(soup.corners, later.corners);
  soup.face_end.reserve(soup.face_count() + later.face_count());
  for (const std::size_t end : later.face_end) soup.face_end.push_back(corners + end);
  std::vector<std::size_t>().swap(later.face_end);
  soup.face_line.append(later.face_line, faces, soup.face_count() - faces, 0);
  later.face_line = FaceLines();
}

}  // namespace holefill::io
