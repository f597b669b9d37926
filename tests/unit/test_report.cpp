// The report (report.h): its figure table names each number once, and the log's time and
// quality lines are that table's figures, in its order, as Figure::Text prints them.
#include "core/report.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <stdexcept>

using namespace eulermap;

namespace {

Report Sample() {
  Report r;
  r.times.sdf = 0.25, r.times.interp = 0.5, r.times.velocity = 1.25, r.times.deform = 0.125;
  r.quality.onSurfaceRate = 0.9979, r.quality.coverage = 0.5, r.quality.anchorErrorCells = 1.5;
  r.cutBoundaryLoops = 2;
  return r;
}

// The line of `text` that starts with `title`.
std::string Line(const std::string &text, const std::string &title) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(title, 0) == 0) return line;
  return "";
}

TEST(Report, EveryFigureHasItsOwnSnakeCaseName) {
  std::set<std::string> names;
  for (const Figure &f : FigureTable()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name << " twice";
    EXPECT_EQ(std::string(f.name).find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_"), std::string::npos) << f.name;
  }
}

TEST(Report, TheTimeLineIsTheTablesTimeFigures) {
  EXPECT_EQ(Line(Sample().ToText(), "times (s)"),
            "times (s): SDF 0.250, INT 0.500, VF 1.250, DEF 0.125, total 2.125, quality measures 0.000");
}

TEST(Report, TheQualityLineIsTheTablesQualityFigures) {
  EXPECT_EQ(Line(Sample().ToText(), "map quality"),
            "map quality: on-surface 99.79%, coverage 50.00%, flipped area 0.00%, longest mapped edge 0.00 cells, "
            "anchor error 1.50 cells, mean distortion 0.000");
}

TEST(Report, FiguresReadTheReport) {
  const Report r = Sample();
  auto figure = [](const std::string &name) {
    for (const Figure &f : FigureTable())
      if (name == f.name) return f;
    throw std::runtime_error("no figure " + name);
  };
  EXPECT_DOUBLE_EQ(figure("time_total_s").value(r), 2.125);
  EXPECT_EQ(figure("cut_boundary_loops").value(r), 2);
  EXPECT_EQ(figure("coverage").Text(r), "50.00%");
}

} // namespace
