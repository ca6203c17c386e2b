#pragma once
// The limits on a world's `map:` section (docs/limits.md): each checked before the work or the
// memory it bounds, each refusal one line naming the file and the limit.

#include <cstddef>
#include <cstdint>

namespace parksim {

inline constexpr std::size_t kMaxMapEntries = 64;             ///< entries of `map:`
inline constexpr std::int64_t kMaxMapSideCells = 20000;       ///< a grid map's width or height
inline constexpr std::int64_t kMaxMapCells = 25'000'000;      ///< width x height of one grid map
inline constexpr std::uintmax_t kMaxMapFileBytes = 1u << 28;  ///< an image or .map file: 256 MiB
inline constexpr std::uintmax_t kMaxMapYamlBytes = 1u << 20;  ///< a ROS map YAML: 1 MiB
inline constexpr std::uintmax_t kMaxSvgFileBytes = 1u << 24;  ///< an SVG drawing: 16 MiB
inline constexpr std::size_t kMaxSvgShapes = 100000;          ///< obstacle shapes of one drawing
/// Vertices of one drawing's shapes after curves are flattened.
inline constexpr std::size_t kMaxSvgVertices = 2'000'000;
/// Convex parts of all of a world's map obstacles together (Bullet children, planner shapes).
inline constexpr std::size_t kMaxMapParts = 1'000'000;

}  // namespace parksim
