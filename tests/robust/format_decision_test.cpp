// The format of a file is decided once: from its first 64 KiB (after a byte-order mark) when it is
// bigger, so that load_mesh can refuse a bad header before reading the rest. That decision must
// be the one its whole contents give (io::sniff on all of it), or left open for the whole to make.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/readers.h"
#include "io/text_scan.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {
namespace fs = std::filesystem;

constexpr std::size_t kStart = (std::size_t{1} << 16) + 3;  // read_file_start's bytes

std::string padded(std::string text, char line) {
  while (text.size() < 3 * kStart) text += std::string(1, line) + " 0 0 0\n";
  return text;
}

std::string binary_stl(std::uint32_t triangles, const std::string& header) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  bytes.append(reinterpret_cast<const char*>(&triangles), 4);  // little-endian hosts
  bytes.append(std::size_t{50} * triangles, '\0');
  return bytes;
}

// Files bigger than their start, of every kind sniffing tells apart or cannot.
std::vector<std::string> big_files() {
  std::string comments;
  while (comments.size() < 100'000) comments += "# a comment line\n";
  const std::string bom = "\xEF\xBB\xBF";
  std::string line_across_start(kStart - 8, '#');  // the "v" line crosses 64 KiB
  line_across_start += "\nv 0 0 0\n";
  std::string long_first_line(70'000, '#');
  long_first_line += "\nOFF\n3 1 0\n\n\n";
  const std::string blanks(70'000, ' ');
  return {padded("ply\nformat ascii 1.0\nend_header\n", '1'),
          padded("OFF\n3 1 0\n", '0'),
          padded("# an OBJ\nv 0 0 0\n", 'v'),
          padded(bom + "v 0 0 0\n", 'v'),
          padded(bom + "OFF\n3 1 0\n", '0'),
          padded(line_across_start, 'v'),
          padded("solid part\n  facet normal 0 0 1\n", 'x'),
          padded(comments + "OFF\n3 1 0\n", '0'),
          long_first_line,
          std::string(70'000, '\0'),
          "ply" + blanks + "x\n",
          "OFF" + blanks + "\n3 1 0\n",
          binary_stl(2'000, "ply\n"),
          binary_stl(2'000, "solid but binary\n"),
          padded(std::string("x\0y", 3), 'z'),
          padded("nothing a mesh holds\n", 'q')};
}

TEST(FormatDecision, TheStartOfAFileDecidesAsTheWholeDoesOrLeavesItOpen) {
  std::size_t decided = 0;
  for (const std::string& file : big_files()) {
    const std::string_view start = std::string_view(file).substr(0, kStart);
    const io::Sniffed sniffed = io::sniff_start(start, file.size());
    if (sniffed.decided) {
      ++decided;
      EXPECT_EQ(sniffed.format, io::sniff(file)) << file.substr(0, 40);
    }
    const std::string_view text = io::without_byte_order_mark(start);
    const io::Sniffed after_mark =
        io::sniff_start(text, file.size() - (start.size() - text.size()));
    if (after_mark.decided) {
      EXPECT_EQ(after_mark.format, io::sniff(io::without_byte_order_mark(file)))
          << file.substr(0, 40);
    }
  }
  // Left open: the two whose keyword comes after comments past the start, and the "ply" whose
  // line runs past it blank so far.
  EXPECT_EQ(decided, big_files().size() - 3);
  // A start too short to look at (the file is bigger) decides nothing.
  EXPECT_FALSE(io::sniff_start("OFF\n3 1 0\n", 100'000).decided);
  EXPECT_TRUE(io::sniff_start("OFF\n3 1 0\n", 10).decided);
}

// An OFF file named .obj whose keyword comes after 100 KB of comments: its start leaves the
// format open, and all of it decides (the contents, with the warning).
TEST(FormatDecision, AFormatTheStartLeavesOpenIsDecidedByTheWholeFile) {
  std::string text;
  while (text.size() < 100'000) text += "# a comment line\n";
  text += "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const fs::path path = fs::temp_directory_path() / "holefill_format_decision_late_keyword.obj";
  std::ofstream(path, std::ios::binary) << text;
  LoadReport report;
  const Mesh mesh = load_mesh(path, &report);
  fs::remove(path);
  EXPECT_EQ(mesh.n_faces(), 1u);
  EXPECT_EQ(report.format, "off");
  ASSERT_FALSE(report.warnings.empty());
  EXPECT_EQ(report.warnings.front(),
            "the contents are OFF, not what the extension '.obj' says; read as OFF");
}

}  // namespace
}  // namespace holefill::testing
