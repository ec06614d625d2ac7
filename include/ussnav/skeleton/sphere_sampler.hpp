#pragma once
// Fibonacci-sphere directions: n unit vectors spread almost uniformly over the sphere, the ray
// directions of ExpandNewPolyhedron (paper Sec. IV-A, 50 by default). Deterministic; O(n).

#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

// n >= 1 unit vectors; point i has z = 1 - (2i + 1) / n and golden-angle longitude, so the
// first points are near the north pole and no two coincide.
std::vector<Vec3> fibonacciSphere(int n);

}  // namespace ussnav
