// What is written is what is judged (docs/semantics.md): the answer ghclip writes by default, and
// with --layout rings, as WKT and as GeoJSON (tools/written_answer.h: ghclip's own code), for every
// workload ghgen knows, plain and with every near-degenerate suffix (one ulp, 1e-300, 1e150, 1e9),
// three seeds, every operation: the bytes read back pass the exact oracle, every OGC answer is
// valid by the exact check (and by GEOS's, where its arithmetic does not underflow), and no answer
// is refused.
#include <geos_c.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ghclip/clipping.h"
#include "ghclip/ogc_layout.h"
#include "ghclip/ogc_validity.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"
#include "ghwork/generators.h"
#include "written_answer.h"

namespace gh {
namespace {

// GEOS's WKT reader and validity test: a second, independent reader of what we write.
class GeosValidity {
 public:
  GeosValidity() : h_(GEOS_init_r()), reader_(GEOSWKTReader_create_r(h_)) {}
  ~GeosValidity() {
    GEOSWKTReader_destroy_r(h_, reader_);
    GEOS_finish_r(h_);
  }
  bool valid(const std::string& wkt) {
    GEOSGeometry* g = GEOSWKTReader_read_r(h_, reader_, wkt.c_str());
    if (!g) return false;
    const bool ok = GEOSisValid_r(h_, g) == 1;
    GEOSGeom_destroy_r(h_, g);
    return ok;
  }

 private:
  GEOSContextHandle_t h_;
  GEOSWKTReader* reader_;
};

// GEOS decides validity in double-double arithmetic (106 bits): below about 1e-150 its products
// underflow, and where coordinates span more than about 2^90 it cannot tell a point 1e-84 above a
// line through 1e10 from one on it (mixed-magnitude+ulp: "Self-intersection" at a hole's vertex
// 7e-84 clear of the shell, which the exact check decides). It is asked only where neither holds.
bool geosCanJudge(const Region& r) {
  double smallest = INFINITY, largest = 0;
  for (const Ring& ring : r) {
    for (const Point& p : ring) {
      for (const double c : {std::abs(p.x), std::abs(p.y)}) {
        if (c != 0) smallest = std::min(smallest, c), largest = std::max(largest, c);
      }
    }
  }
  return smallest > 1e-140 && largest < 0x1p90 * smallest;
}

// Rings as read, without the closing point the text repeats.
Region open(Region r) {
  for (Ring& ring : r) {
    if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  }
  return r;
}

TEST(WrittenAnswers, EveryWorkloadEverySuffixPassesTheExactOracleAsWritten) {
  GeosValidity geos;
  int problems = 0, answers = 0, refusals = 0, snapRounded = 0, notGenerated = 0, geosJudged = 0;
  std::vector<std::string> suffixes{""};
  for (const std::string& s : work::variantSuffixes()) suffixes.push_back("+" + s);
  for (const std::string& workload : work::workloadNames()) {
    for (const std::string& suffix : suffixes) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        // Sizes that differ by seed, up to 16: the shapes' own minimum to where pies get crowded.
        const std::size_t n = std::size_t{4} + 6 * (seed - 1);
        const std::string name = workload + suffix;
        work::Workload w;
        try {
          w = work::generate(name, n, seed);
        } catch (const std::invalid_argument& e) {
          // Only a suffix that takes mixed-magnitude's small star below the doubles does this.
          EXPECT_EQ(workload, "mixed-magnitude") << e.what();
          ++notGenerated;
          continue;
        }
        ++problems;
        Clipping clipping(w.subject, w.clip);
        std::vector<oracle::Answer> judged;
        std::vector<std::string> labels;
        for (const Op op : kAllOps) {
          for (const io::Layout layout : {io::Layout::Ogc, io::Layout::Rings}) {
            const std::string where = name + " seed " + std::to_string(seed) + " " + std::string(gh::name(op)) +
                                      (layout == io::Layout::Ogc ? " ogc" : " rings");
            Region read[2];
            int k = 0;
            for (const io::Format format : {io::Format::Wkt, io::Format::GeoJson}) {
              tools::WrittenAnswer a;
              try {
                a = tools::writtenAnswer(clipping, w.subject, w.clip, op, format, layout);
              } catch (const LayoutRefusal& e) {
                ADD_FAILURE() << where << ": refused: " << e.what();
                ++refusals;
                break;
              }
              snapRounded += a.layout.snapRounded && format == io::Format::Wkt;
              read[k++] = io::readAuto(a.text);
              if (layout == io::Layout::Ogc) {
                const auto invalid = ogcInvalidity(a.polygons);
                EXPECT_FALSE(invalid) << where << ": " << *invalid;
                EXPECT_EQ(open(read[k - 1]), toRegion(a.polygons)) << where << ": the text does not read back as written";
                if (format == io::Format::Wkt && geosCanJudge(read[0])) {
                  EXPECT_TRUE(geos.valid(a.text)) << where << ": GEOS reads it invalid";
                  ++geosJudged;
                }
              }
              ++answers;
            }
            if (k < 2) continue;
            // WKT and GeoJSON carry the same doubles: one judgement serves both.
            EXPECT_EQ(read[0], read[1]) << where << ": WKT and GeoJSON differ";
            judged.push_back({op, read[0]});
            labels.push_back(where);
          }
        }
        const std::vector<oracle::ExactVerdict> verdicts = oracle::exactCheckAll(w.subject, w.clip, judged);
        for (std::size_t i = 0; i < verdicts.size(); ++i) {
          EXPECT_TRUE(verdicts[i].pass) << labels[i] << ": beyond rounding, relative "
                                        << verdicts[i].relativeBeyondRounding();
        }
      }
    }
  }
  EXPECT_EQ(refusals, 0);
  EXPECT_GT(snapRounded, 0) << "no answer needed snap rounding: the subnormal pies no longer reach it";
  EXPECT_GT(geosJudged, 0);
  RecordProperty("problems", problems);
  RecordProperty("answers", answers);
  RecordProperty("snap_rounded", snapRounded);
  RecordProperty("not_generated", notGenerated);
  std::printf("%d problems (%d not generated), %d answers written and read back, %d snap-rounded, %d read by GEOS\n",
              problems, notGenerated, answers, snapRounded, geosJudged);
}

}  // namespace
}  // namespace gh
