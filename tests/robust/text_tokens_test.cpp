// The token rules of the OBJ and OFF readers, which read numbers in place and serve the usual
// face corners on a fast path: a number is a whole blank-separated token (one followed by
// anything else is refused, quoted as before), '+' signs are taken but not "+-", every corner
// spelling reads as the slow path splits it, and lines end at LF, CR LF or a lone CR in any mix.
// The expected messages are those of the readers before the fast paths.
#include <sys/mman.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "io/readers.h"
#include "io/text_scan.h"
#include "robust_test_util.h"

namespace holefill::testing {
namespace {

constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
constexpr const char* kTriangleOff = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";

TEST(TextTokens, EveryObjCornerSpellingReadsAsOneFace) {
  const std::string t = kTriangleObj;
  for (const std::string faces :
       {"f 1/ 2// 3\n", "f +1 +2 +3\n", "f -3 -2 -1\n", "f 1\t2\v3\f\n", " \tfo 1 2 3 # c\n",
        "f 1 2\\\n 3\n", "vt 0 0\nf 1/1/ 2/1 3/-1\n", "vn 0 0 1\nf 1//1 2//+1 3//-1\n"}) {
    LoadReport report;
    const Mesh mesh = load_mesh_from_memory(t + faces, "t.obj", &report);
    EXPECT_EQ(mesh.n_faces(), 1u) << faces;
    EXPECT_TRUE(report.warnings.empty()) << faces << report.warnings.front();
  }
  LoadReport report;
  load_mesh_from_memory(t + "vt 0 0\nf 1/1 2/1 3/\n", "t.obj", &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            "1 faces gave texture coordinates to some of their corners only; those were dropped");
}

TEST(TextTokens, ObjNumbersFollowedByOtherCharactersAreRefusedAsBefore) {
  const std::string t = kTriangleObj;
  EXPECT_EQ(refusal(t + "v 0 0 0x\n", "t.obj"), "line 4: vertex needs 3 numbers, got '0x'");
  EXPECT_EQ(refusal(t + "v +-1 0 0\n", "t.obj"), "line 4: vertex needs 3 numbers, got '+-1'");
  EXPECT_EQ(refusal(t + "v 1e999 0 0\n", "t.obj"),
            "line 4: vertex 4 has a non-finite (NaN or infinite) coordinate");
  EXPECT_EQ(refusal(t + "f 1 2 3x\n", "t.obj"), "line 4: face corner '3x' is not a vertex index");
  EXPECT_EQ(refusal(t + "f 1 2 +-3\n", "t.obj"), "line 4: face corner '+-3' is not a vertex index");
  EXPECT_EQ(refusal(t + "f 1 2 99999999999999999999\n", "t.obj"),
            "line 4: face corner '99999999999999999999' is not a vertex index");
  EXPECT_EQ(refusal(t + "vt 0 0\nf 1/1/ 2/1 3/1//\n", "t.obj"),
            "line 5: face corner '3/1//' has no valid normal index");
  EXPECT_EQ(refusal(t + "vn 0 0 1\nf 1//1 2//1 3//1/\n", "t.obj"),
            "line 5: face corner '3//1/' has no valid normal index");
  // A bad index before a syntax error is named first, as the corners come.
  EXPECT_EQ(refusal(t + "f 0 2 3x\n", "t.obj"), "line 4: vertex index 0 (OBJ counts from 1)");
  // Underflow reads as a tiny number; colours that are not numbers are not colours.
  EXPECT_EQ(refusal(t + "v 1e-400 0 0 1 1 1x\nf 1 2 4\n", "t.obj"), "");
}

TEST(TextTokens, OffNumbersFollowedByOtherCharactersAreRefusedAsBefore) {
  const std::string t = kTriangleOff;
  EXPECT_EQ(refusal(t + "+3 +0 +1 +2\n", "t.off"), "");
  EXPECT_EQ(refusal(t + "3\t0\v1\f2\n", "t.off"), "");
  EXPECT_EQ(refusal(t + "3 0 1 2x\n", "t.off"), "line 6: face needs 3 vertex indices, got '2x'");
  EXPECT_EQ(refusal(t + "3 0 1 +-2\n", "t.off"), "line 6: face needs 3 vertex indices, got '+-2'");
  EXPECT_EQ(refusal(t + "3x 0 1 2\n", "t.off"),
            "line 6: a face must start with its number of corners, got '3x'");
  EXPECT_EQ(refusal(t + "-1 0 1 2\n", "t.off"),
            "line 6: a face must start with its number of corners, got '-1'");
  EXPECT_EQ(refusal(t + "3 0 1\n", "t.off"), "line 6: face needs 3 vertex indices");
  EXPECT_EQ(refusal(t + "3 0 1 2 0.5 0.5 0.5x\n", "t.off"),
            "line 6: expected a number, got '0.5x'");
  EXPECT_EQ(refusal("OFF\n3 1 0\n0 0 0x\n1 0 0\n0 1 0\n3 0 1 2\n", "t.off"),
            "line 3: vertex needs 3 numbers, got '0x'");
  EXPECT_EQ(refusal("COFF\n3 1 0\n0 0 0 1 2 3\n1 0 0 1 2 3x\n0 1 0\n3 0 1 2\n", "t.off"),
            "line 4: expected a number, got '3x'");
}

// Numbers in the spellings exporters use and at the edges of exact parsing (53-bit mantissas,
// powers of ten past 22, integers past 18 digits, signs, exponents): take_double, read in place,
// and take_integer_prefix give what from_chars gives on the whole token, bit for bit, and stop
// where it stops.
std::vector<std::string> number_spellings() {
  std::mt19937_64 random(7);
  std::vector<std::string> spellings = {"0",
                                        "-0",
                                        "0.0",
                                        "-0.0",
                                        ".5",
                                        "5.",
                                        "-.5",
                                        "1e22",
                                        "1e23",
                                        "1e-22",
                                        "1e-23",
                                        "9007199254740992",
                                        "9007199254740993",
                                        "-9007199254740993e-5",
                                        "123456789012345678",
                                        "1234567890123456789",
                                        "12345678901234567890",
                                        "0.00000000000000000001",
                                        "9223372036854775807",
                                        "-9223372036854775808",
                                        "9223372036854775808",
                                        "1e",
                                        "1e+",
                                        "1e0022",
                                        "1E-7",
                                        "1.5e+3",
                                        "4.9406564584124654e-324",
                                        "1.7976931348623157e308",
                                        "1e99999",
                                        "inf",
                                        "nan",
                                        "0x10",
                                        "--1",
                                        "-",
                                        ".",
                                        "1.2.3",
                                        "007",
                                        "-000000000000000000001"};
  // The short decimal path's edges: 19 and 20 digits, 8 and 16 (read eight at a time), a
  // mantissa of 2^53 and one past it, powers of ten 22 and 23 either way after the fraction's
  // digits, exponents of 3 and 4 digits, a bare point, signs, what strtod reads and from_chars
  // does not.
  spellings.insert(spellings.end(), {"1234567890.123456789",
                                     "1234567890.1234567891",
                                     "0000000000000000000.5",
                                     "12345678",
                                     "1234567812345678",
                                     "0.12345678",
                                     "9007199254740.992",
                                     "9007199254740.993",
                                     "900719925474099.3e-20",
                                     "0.5e-21",
                                     "0.5e-22",
                                     "0.05e24",
                                     "0.05e23",
                                     "123.456e20",
                                     "123.456e21",
                                     "1e-022",
                                     "1e999",
                                     "-0e-5",
                                     "0e-400",
                                     "1.e5",
                                     "+.5",
                                     ".e5",
                                     "1.5e",
                                     "1.5e-",
                                     "1.5e+-3",
                                     "1.5E+003",
                                     "0.1\r",
                                     "1e5.5",
                                     "0x1p3",
                                     "infinity",
                                     "-nan"});
  char text[64];
  for (int i = 0; i < 4000; ++i) {
    const double magnitude = std::ldexp(std::uniform_real_distribution<>(-1, 1)(random),
                                        static_cast<int>(random() % 80) - 40);
    const auto as_float = static_cast<float>(magnitude);
    spellings.emplace_back(text, std::to_chars(text, text + 64, as_float).ptr);
    spellings.emplace_back(text, std::to_chars(text, text + 64, magnitude).ptr);
    std::snprintf(text, sizeof text, "%.17g", magnitude);
    spellings.emplace_back(text);
    std::snprintf(text, sizeof text, "%.*f", static_cast<int>(random() % 12), magnitude);
    spellings.emplace_back(text);
    std::snprintf(text, sizeof text, "%.*e", static_cast<int>(random() % 20), magnitude);
    spellings.emplace_back(text);
    spellings.push_back(std::to_string(static_cast<long long>(random() >> (random() % 64))));
    spellings.push_back(std::to_string(-static_cast<long long>(random() >> (random() % 64))));
    spellings.push_back(std::to_string(random() % 100000000) + "/" + std::to_string(i));
  }
  return spellings;
}

TEST(TextTokens, NumbersReadInPlaceAreWhatFromCharsReads) {
  for (const std::string& spelling : number_spellings()) {
    // Eight bytes or more from the first digit on are read eight at a time.
    for (const std::string& text : {spelling, spelling + " 1", spelling + "x", "+" + spelling,
                                    spelling + "/1234567 8", "+" + spelling + "\t\t\t\t\t\t\t\t"}) {
      std::string_view in_place = text, token = text;
      double fast = 0, slow = 0;
      const bool fast_read = io::take_double(in_place, fast);
      const bool slow_read = io::parse_double(io::take_token(token), slow);
      ASSERT_EQ(fast_read, slow_read) << text;
      if (fast_read) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(fast), std::bit_cast<std::uint64_t>(slow)) << text;
        EXPECT_EQ(in_place, token) << text;
      }
      // The integer prefix: what from_chars reads of it (after one '+'), and where it stops.
      std::string_view rest = text;
      long long integer = 0, expected = 0;
      const std::size_t plus = text.starts_with("+") && !text.starts_with("+-") ? 1 : 0;
      const auto [stop, error] =
          std::from_chars(text.data() + plus, text.data() + text.size(), expected);
      ASSERT_EQ(io::take_integer_prefix(rest, integer), error == std::errc()) << text;
      if (error == std::errc()) {
        EXPECT_EQ(integer, expected) << text;
        EXPECT_EQ(rest.data(), stop) << text;
      }
    }
  }
}

// Whatever strtod reads whole (in the C locale) that is decimal, take_double reads to the same
// double, bit for bit; it refuses hexadecimal numbers, which from_chars does not read, and
// reads nothing strtod would not.
TEST(TextTokens, DecimalNumbersReadAsStrtodReadsThem) {
  for (const std::string& spelling : number_spellings()) {
    std::string_view text = spelling;
    double value = 0;
    const bool read = io::take_double(text, value);
    char* stop = nullptr;
    const double expected = std::strtod(spelling.c_str(), &stop);
    const bool whole = !spelling.empty() && *stop == '\0';
    const bool hexadecimal = spelling.find_first_of("xX") != std::string::npos;
    const bool trailing_blank = spelling.back() == '\r';
    if (hexadecimal || trailing_blank) {
      EXPECT_EQ(read, trailing_blank) << spelling;
      continue;
    }
    ASSERT_EQ(read, whole) << spelling;
    if (read && !std::isnan(expected)) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(value), std::bit_cast<std::uint64_t>(expected))
          << spelling;
    }
  }
}

TEST(TextTokens, MixedLineEndsCountLinesAsBefore) {
  // CR LF, a lone CR, LF; then "\r\r\n\n" is three empty lines.
  EXPECT_EQ(refusal("v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\r\r\n\nv 1 x 0\n", "t.obj"),
            "line 7: vertex needs 3 numbers, got 'x'");
  EXPECT_EQ(refusal("OFF\r3 1 0\n\r0 0 0\r\n1 0 0\r0 1 0\n\n3 0 1 7\n", "t.off"),
            "line 8: face refers to vertex 7, but the file has 3 vertices (numbered from 0)");
}

// A text whose bytes past its first 64 KB cannot be read (the pages are mapped without access):
// sniffing it reads only its start, where it searched the whole text for a CR before (a 100 MB
// file was read once more, on one thread, before its reader started).
TEST(FormatSniff, ReadsOnlyTheStartOfAText) {
  constexpr std::size_t kReadable = std::size_t{1} << 16, kUnreadable = std::size_t{1} << 20;
  void* pages = mmap(nullptr, kReadable + kUnreadable, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(pages, MAP_FAILED);
  char* bytes = static_cast<char*>(pages);
  ASSERT_EQ(mprotect(bytes + kReadable, kUnreadable, PROT_NONE), 0);
  const std::pair<std::string, MeshFormat> starts[] = {
      {"ply\nformat ascii 1.0\n", MeshFormat::Ply},
      {"# made by hand\n\nOFF\n3 1 0\n", MeshFormat::Off},
      {"mtllib a.mtl\nv 0 0 0\n", MeshFormat::Obj}};
  for (const auto& [start, format] : starts) {
    std::memset(bytes, ' ', kReadable);
    std::memcpy(bytes, start.data(), start.size());
    bytes[kReadable - 1] = '\n';
    EXPECT_EQ(io::sniff(std::string_view(bytes, kReadable + kUnreadable)), format) << start;
  }
  munmap(pages, kReadable + kUnreadable);
}

// The first line with a keyword decides, wherever it is: after 100 KB of comments, and on a line
// that crosses 64 KB from the start.
TEST(FormatSniff, TheFirstKeywordLineDecidesAfterAnyNumberOfComments) {
  std::string comments;
  while (comments.size() < 100'000) comments += "# a comment line, then an empty one\n\n";
  EXPECT_EQ(io::sniff(comments + "OFF\n3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(io::sniff(comments + "ply\r\nformat ascii 1.0\n"), MeshFormat::Ply);
  EXPECT_EQ(io::sniff(comments), std::nullopt);
  for (const std::size_t before : {std::size_t{65'534}, std::size_t{65'535}, std::size_t{65'536}}) {
    const std::string start = std::string(before - 1, '#') + "\n";
    EXPECT_EQ(io::sniff(start + "   OFF  \n3 1 0\n"), MeshFormat::Off) << before;
    EXPECT_EQ(io::sniff(start + "  ply \t\nformat ascii 1.0\n"), MeshFormat::Ply) << before;
    // "ply" with more on its line is no PLY header line.
    EXPECT_NE(io::sniff(start + "ply" + std::string(10, ' ') + "x\n"), MeshFormat::Ply) << before;
  }
}

}  // namespace
}  // namespace holefill::testing
