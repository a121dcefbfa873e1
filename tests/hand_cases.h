// Hand-checked clipping cases: every expected area below is worked out by hand in the comment
// beside it (rectangles, triangles, and the regular pentagram's closed form).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ghclip/operation.h"
#include "ghclip/region.h"

namespace gh::test {

struct HandCase {
  std::string name;
  Region subject, clip;
  double areaSubject, areaClip;
  // Expected even-odd areas of intersection, union, difference, reverse difference, xor.
  double expected[5];
  int intersectionRings = -1;  // expected ring count of the intersection, -1 if not checked
};

inline Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Regular pentagram with circumradius 1 drawn as one self-intersecting ring (every second
// vertex of a regular pentagon), tip at (0, 1). Its even-odd interior is the five points; the
// central pentagon has winding number 2 and is outside.
inline Ring pentagram() {
  Ring ring;
  const double pi = std::acos(-1.0);
  for (int k = 0; k < 5; ++k) {
    const double a = pi / 2 + 2 * pi * (2 * k) / 5;
    ring.push_back({std::cos(a), std::sin(a)});
  }
  return ring;
}

// Even-odd area of the pentagram, by hand: the star outline is a decagon with alternating radii
// R = 1 and r = cos 72 / cos 36 (the inner pentagon's circumradius), area 5 R r sin 36; the
// inner pentagon has area (5/2) r^2 sin 72; the points are the difference. = 0.7756...
inline double pentagramArea() {
  const double pi = std::acos(-1.0);
  const double r = std::cos(2 * pi / 5) / std::cos(pi / 5);
  return 5 * r * std::sin(pi / 5) - 2.5 * r * r * std::sin(2 * pi / 5);
}

inline std::vector<HandCase> handCases() {
  const double star = pentagramArea();
  return {
      // [0,2]^2 and [1,3]^2 overlap in [1,2]^2.
      {"convex_squares", {rect(0, 0, 2, 2)}, {rect(1, 1, 3, 3)}, 4, 4, {1, 7, 3, 3, 6}, 1},
      // U shape: [0,3]^2 minus the notch [1,2]x[1,3] (area 9 - 2 = 7); clip [0.5,2.5]x[2,4]
      // (area 4) meets both arms in [0.5,1]x[2,3] and [2,2.5]x[2,3]: 0.5 + 0.5.
      {"concave_u",
       {{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}},
       {rect(0.5, 2, 2.5, 4)},
       7,
       4,
       {1, 10, 6, 3, 9},
       2},
      // Paper, Figure 7 style: square [0,4]^2 and a clip shaped like a gate whose two legs,
      // [0.5,1.5]x[2,5] and [2.5,3.5]x[2,5], hang from the bar [0.5,3.5]x[5,6] (area 3 + 3 + 3).
      // The legs enter the square through its top edge: two rings of 1 x 2 each.
      {"figure7_gate",
       {rect(0, 0, 4, 4)},
       {{{0.5, 2}, {1.5, 2}, {1.5, 5}, {2.5, 5}, {2.5, 2}, {3.5, 2}, {3.5, 6}, {0.5, 6}}},
       16,
       9,
       {4, 21, 12, 5, 17},
       2},
      // Square [0,4]^2 with hole [1,3]^2 (area 12); clip [2,6]x[-1,5] (area 24). Inside the clip:
      // [2,4]x[0,4] = 8 minus the hole's right half [2,3]x[1,3] = 2.
      {"square_with_hole_half",
       {rect(0, 0, 4, 4), rect(1, 1, 3, 3)},
       {rect(2, -1, 6, 5)},
       12,
       24,
       {6, 30, 6, 18, 24},
       1},
      // Same square with hole; clip [0.5,3.5]^2 (area 9) contains the hole: 9 - 4 = 5.
      {"square_with_hole_around",
       {rect(0, 0, 4, 4), rect(1, 1, 3, 3)},
       {rect(0.5, 0.5, 3.5, 3.5)},
       12,
       9,
       {5, 16, 7, 4, 11},
       -1},
      // Bow-tie (0,0)-(2,2)-(2,0)-(0,2): two triangles of area 1 meeting at (1,1). The clip
      // [-0.5,1.5]x[-1,3] (area 8) holds the left triangle (1) and of the right one the part
      // with x in [1,1.5], whose height is 2x - 2: integral = 0.25.
      {"bowtie",
       {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}},
       {rect(-0.5, -1, 1.5, 3)},
       2,
       8,
       {1.25, 8.75, 0.75, 6.75, 7.5},
       -1},
      // Pentagram against the half-plane square [0,2]x[-2,2] (area 8): by the star's mirror
      // symmetry in the y axis, exactly half of its even-odd area is inside.
      {"pentagram_half_square",
       {pentagram()},
       {rect(0, -2, 2, 2)},
       star,
       8,
       {star / 2, 8 + star / 2, star / 2, 8 - star / 2, 8},
       -1},
      // Pentagram inside the square [-2,2]^2 (area 16): no crossings, one point-in-region test.
      {"pentagram_in_square",
       {pentagram()},
       {rect(-2, -2, 2, 2)},
       star,
       16,
       {star, 16, 0, 16 - star, 16 - star},
       -1},
      // Disjoint unit squares.
      {"disjoint", {rect(0, 0, 1, 1)}, {rect(2, 0, 3, 1)}, 1, 1, {0, 2, 1, 1, 2}, 0},
      // [1,2]^2 nested in [0,4]^2.
      {"nested", {rect(0, 0, 4, 4)}, {rect(1, 1, 2, 2)}, 16, 1, {1, 16, 15, 0, 15}, 1},
      // Empty clip.
      {"empty_clip", {rect(0, 0, 4, 4)}, {}, 16, 0, {0, 16, 16, 0, 16}, 0},
  };
}

}  // namespace gh::test
