// The viewer's colours, in one place: the renderer draws with them and the GUI test's pixel
// checker looks for them (the boundary and divider colours are unlit, so they land exactly).
#pragma once

#include <array>
#include <cstdint>

namespace holefill::viewer::palette {

using Rgb = std::array<std::uint8_t, 3>;

inline constexpr Rgb kBackground{33, 36, 43};
inline constexpr Rgb kSurface{200, 190, 174};      // original faces
inline constexpr Rgb kTriangulated{77, 140, 242};  // faces the triangulation added
inline constexpr Rgb kRefined{89, 204, 115};       // faces the refinement added
inline constexpr Rgb kSmoothed{165, 135, 235};     // faces of a smoothed patch
inline constexpr Rgb kWireframe{40, 40, 48};
inline constexpr Rgb kPatchVertex{230, 40, 25};
inline constexpr Rgb kBoundary{255, 140, 0};  // an unfilled hole's boundary loop
inline constexpr Rgb kBorder{0, 170, 150};    // a loop that looks like an open surface's border
inline constexpr Rgb kSelectedBoundary{255, 0, 255};
inline constexpr Rgb kJoinedBoundary{255, 150, 255};  // filled with the selected hole: islands
inline constexpr Rgb kHoveredBoundary{0, 255, 255};
inline constexpr Rgb kDivider{255, 216, 0};       // between the comparison's two views
inline constexpr Rgb kFeatureLine{255, 230, 60};  // a sharp feature entering the hole
inline constexpr Rgb kFeaturePath{60, 255, 120};  // its continuation across the hole

}  // namespace holefill::viewer::palette
