// The raw lines of an OBJ file checked before tinyobjloader reads them. tinyobjloader reads `nan`,
// `inf` and junk coordinates as 0, accepts 2-component vertices, wraps an index too large for an
// int into a valid one, lets one bad texture-coordinate index drop a whole mesh's uvs, and reports
// indices after its own conversion; its polygon triangulation grows as the square of a face's
// corners (a 2.2 MB face of 100,000 corners took 165 s). Each of these is refused here with the
// OBJ's line, the keyword and the value as written.
#pragma once

#include <cstddef>
#include <string>

namespace vkrt {

// Faces with more corners are refused: 4096 corners triangulate in about 0.07 s on this project's
// machines (16384 in about 1 s), so a file of them stays proportionate to its size.
inline constexpr std::size_t kMaxObjFaceCorners = 4096;

// Throws std::runtime_error "OBJ line N: <keyword>: <problem> '<value>'" at the first bad line:
// v/vn with other than 3 coordinates (v may add w, or r g b), vt with 0 or more than 3, a
// coordinate that is not a finite float, a face of fewer than 3 or more than kMaxObjFaceCorners
// corners, an index that is not an integer, 0, beyond int, or naming a v/vt/vn not defined before
// the line (tinyobjloader takes no forward references either). Other keywords are left to the loader.
void validateObjText(const std::string& text);

}  // namespace vkrt
