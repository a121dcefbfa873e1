// Two unit squares overlapping by half: the intersection's even-odd area is 0.5.
#include <ghclip/clip.h>
#include <ghclip/measure.h>

#include <cstdio>

int main() {
  const gh::Region a{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const gh::Region b{{{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}}};
  const double area = gh::evenOddArea(gh::clip(a, b, gh::Op::Intersection));
  std::printf("%g\n", area);
  return area == 0.5 ? 0 : 1;
}
