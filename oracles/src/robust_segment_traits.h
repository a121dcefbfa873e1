// CGAL's segment traits with one functor replaced: the crossing point of two segments.
//
// Arr_segment_traits_2::Intersect_2 intersects the two supporting lines with the kernel's
// Line_2/Line_2 intersection, which returns "no intersection" when a numerator is not finite
// (Intersections_2/Line_2_Line_2.h, CGAL 5.5). Under the lazy exact kernel that test runs on the
// interval approximation: with coordinates near 2^120, numerators of degree 3 overflow to
// infinity, the lazy kernel trusts the approximation's "no intersection", and the sweep then
// dereferences the empty result (a segmentation fault in release builds, an assertion with CGAL
// checks on). Here the point is built from the same line coefficients with the kernel's number
// type, whose approximations may overflow but whose exact values never do. Everything else is
// CGAL's.
#pragma once

#include <CGAL/Arr_segment_traits_2.h>

#include <boost/variant.hpp>
#include <utility>

namespace gh::oracle {

template <class Kernel>
class RobustSegmentTraits : public CGAL::Arr_segment_traits_2<Kernel> {
  using Base = CGAL::Arr_segment_traits_2<Kernel>;

 public:
  using typename Base::Multiplicity;
  using typename Base::Point_2;
  using typename Base::X_monotone_curve_2;

  // CGAL's functor, with the one case its line intersection gets wrong computed here.
  class Intersect_2 : public Base::Intersect_2 {
   public:
    explicit Intersect_2(const RobustSegmentTraits& traits) : Base::Intersect_2(traits) {}

    template <class OutputIterator>
    OutputIterator operator()(const X_monotone_curve_2& a, const X_monotone_curve_2& b,
                              OutputIterator out) const {
      using Crossing = std::pair<Point_2, Multiplicity>;
      using Result = boost::variant<Crossing, X_monotone_curve_2>;
      if (!this->do_bboxes_overlap(a, b) || !this->do_intersect(a.left(), a.right(), b.left(), b.right())) {
        return out;
      }
      const Kernel& kernel = this->m_traits;
      const auto& la = a.line();
      const auto& lb = b.line();
      if (const auto found = kernel.intersect_2_object()(la, lb)) {
        if (const Point_2* p = boost::get<Point_2>(&*found)) {
          *out++ = Result(Crossing(*p, Multiplicity(1)));
          return out;
        }
        return Base::Intersect_2::operator()(a, b, out);  // one line: the overlap, CGAL's own code
      }
      // "No intersection" of two segments known to meet: the approximation overflowed. The
      // point from the line coefficients in the kernel's number type, whose exact values never do
      // (the lines are not parallel: parallel segments that meet lie on one line).
      const auto denominator = la.a() * lb.b() - lb.a() * la.b();
      const auto x = (la.b() * lb.c() - lb.b() * la.c()) / denominator;
      const auto y = (lb.a() * la.c() - la.a() * lb.c()) / denominator;
      *out++ = Result(Crossing(Point_2(x, y), Multiplicity(1)));
      return out;
    }
  };

  Intersect_2 intersect_2_object() const { return Intersect_2(*this); }
};

}  // namespace gh::oracle
