#pragma once
// The limits every reader checks before a parser sees the input (issue 24; docs/cli.md "Limits"):
// nlohmann's dump(), TinyXML's element parser and urdfdom's link tree recurse once per level, so
// input nested or chained beyond what a program's stack holds would crash them. Each limit is far
// above what a robot, pose, platform or scene file needs, and an input beyond it is refused with a
// message naming the file and the limit (InvalidInput, exit 2).
#include <cstddef>

namespace soma::io::limits {

/// The largest input file soma reads: 16 MiB (a URDF with inline meshes is a few MiB; a robot,
/// pose, platform or scene file a few KiB). Read in bounded pieces, so that /dev/zero or a pipe
/// that never ends is refused instead of filling the memory.
inline constexpr std::size_t maxFileBytes = std::size_t(16) << 20;

/// JSON arrays and objects, and XML elements, nested deeper than this are refused (a robot file
/// nests 5 levels: robot → joints → [i] → limits → [k]; a URDF 4: robot → joint → limit).
inline constexpr std::size_t maxDepth = 64;

/// A robot (JSON or URDF) with more joints than this is refused: a serial chain of soma has at
/// most a few dozen joints, and urdfdom destroys its link tree recursively (one frame per link).
inline constexpr std::size_t maxJoints = 1000;

/// A URDF with more elements than this is refused (links, joints and their children).
inline constexpr std::size_t maxXmlElements = 100000;

}  // namespace soma::io::limits
