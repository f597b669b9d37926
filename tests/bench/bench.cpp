// eulermap_bench — the pipeline on configurations shaped like the paper's Table 1, and
// on any two mesh files. One invocation measures one configuration (so that the peak
// memory figure is that configuration's own); tests/bench/run collects the table.
//
//   eulermap_bench row N [--threads T] [--solver mg|cg|gs] [--deformation S]
//                                                          one of the four Table 1 rows (N = 1..4)
//   eulermap_bench grid CELLS [--threads T]                sphere -> ellipsoid on a grid of CELLS^3 nodes
//   eulermap_bench load N                                   row N quiet, then beside one CPU-bound process per
//                                                           core, at nice 0 and at nice 10, 3 rounds: the wall
//                                                           times, their medians and the medians' ratios
//   eulermap_bench vertices S                               sphere of S subdivisions -> ellipsoid, 64 cells
//   eulermap_bench soup S                                   sphere of S subdivisions -> torus, 64 cells, welded
//                                                           and as a triangle soup (every face its own vertices)
//   eulermap_bench map SOURCE TARGET [SOURCE.pp TARGET.pp] [--grid N] [--steps N] [--images FILE] [--save DIR]
//                                                           FILE: a line per source vertex, its image on the
//                                                           target "x y z 1", or "x y z 0" where surgery removed
//                                                           it (the image of the nearest kept vertex)
//   options of every mode: --alpha A --anchor-weight B --anchor-radius R (velocity.h) --align none|centre
//                          --no-untangle (untangle.h left out: the map before untangling, stretched edges still split)
//   eulermap_bench header                                   the header of the table `row` and `grid` print
//   eulermap_bench mlx [NAME=VALUE ...]                     a complete meshlabserver script of the filter
//                                                           (core/parameters.h; defaults for the rest)
//   eulermap_bench parameters                               the README's parameter list
//
// `row` and `grid` print one line of the table (`|`-separated); `map` prints the report.
#include "tests/support/busy.h"
#include "tests/support/correspondence.h"
#include "tests/support/meshes.h"
#include "tests/support/shapes.h"

#include "core/parameters.h"

#include <wrap/io_trimesh/export_ply.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

struct Row {
  const char *mesh;  // source, from ../shared/data/meshes
  int refinements;   // midpoint subdivisions of every edge, to reach the paper's vertex count
  vcg::Point3i nodes;
  int anchors;
  double deformation;  // strength of Bend for the target
  // Paper, Table 1: vertices and seconds for INT, VF, DEF.
  int paperVertices;
  double paperInt, paperVf, paperDef;
};

// Row 2 has no anchors, so its morph is the linear blend of f0 and f1 (Eq. 1), which carries
// a part only where source and target overlap. At full strength Bend moves the bunny's
// ears by more than their thickness: the blend dissolves them and grows the target's out of
// nothing, which no point reaches (coverage 88-90% at 30x40x30 and 88.8% at 60x80x60).
// Row 2 uses half the deformation; `--deformation 1` shows the full one.
const Row kRows[4] = {
    {"camelhead.off", 0, {50, 40, 120}, 15, 1, 11488, 25, 180, 14},
    {"bunny.off", 1, {30, 40, 30}, 0, 0.5, 14425, 0.3, 26, 17},
    {"decimated-knight.off", 2, {100, 80, 50}, 30, 1, 8078, 85, 324, 10},
    {"camelhead.off", 1, {40, 30, 40}, 21, 1, 44170, 8, 34, 56},
};

// The row's columns: the configuration, its grid, the figures of the report marked for the
// benchmark (report.h, FigureTable()), the speed-ups, the velocity solver.
std::string Header() {
  std::string text = "configuration | grid nodes";
  for (const Figure &f : FigureTable())
    if (f.benchmark)
      text += std::string(" | ") + f.label +
              (f.unit == FigureUnit::Share ? " %" : f.unit == FigureUnit::Seconds ? " s" : f.unit == FigureUnit::Cells ? ", cells" : "");
  return text + " | speed-up over the paper, our SDF included | speed-up, INT+VF+DEF only (the paper's columns) | velocity solver";
}

// The speed-ups: the paper's INT+VF+DEF over ours with our SDF included (the paper's table
// has no SDF column), and over our INT+VF+DEF alone (like for like).
void PrintRow(const std::string &name, const Report &r, double paperTotal) {
  const StageTimes &t = r.times;
  auto ratio = [&](double ours) {
    char text[32] = "";
    if (paperTotal > 0) std::snprintf(text, sizeof text, "%.1f", paperTotal / ours);
    return std::string(text);
  };
  std::printf("%s | %dx%dx%d", name.c_str(), r.gridNodes.X(), r.gridNodes.Y(), r.gridNodes.Z());
  for (const Figure &f : FigureTable()) {
    if (!f.benchmark) continue;
    std::string text = f.Text(r);
    if (f.unit == FigureUnit::Share) text.pop_back();  // the header says %
    if (f.unit == FigureUnit::Cells) text.resize(text.size() - 6);  // " cells": the header says so
    std::printf(" | %s", text.c_str());
  }
  std::printf(" | %s | %s | %s\n", ratio(t.Total()).c_str(), ratio(t.interp + t.velocity + t.deform).c_str(),
              r.solver.c_str());
}

// "name=value" arguments from argv[first] on.
const char *StringFlag(int argc, char **argv, const char *name) {
  for (int i = 0; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], name)) return argv[i + 1];
  return nullptr;
}

// Whether argv holds the argument `name`.
bool HasFlag(int argc, char **argv, const char *name) {
  return std::any_of(argv, argv + argc, [&](const char *a) { return !std::strcmp(a, name); });
}

// Each source vertex's image and whether surgery kept it (correspondence.h), a line each,
// for the correspondence benchmark (tests/bench/topkids.py).
void WriteImages(const Mesh &source, Result &result, const char *path) {
  std::vector<char> kept;
  const std::vector<Point3> images = SourceImages(source, result, &kept);
  FILE *out = std::fopen(path, "w");
  if (!out) throw std::runtime_error(std::string("cannot write ") + path);
  for (std::size_t v = 0; v < images.size(); ++v)
    std::fprintf(out, "%.9g %.9g %.9g %d\n", images[v].X(), images[v].Y(), images[v].Z(), int(kept[v]));
  std::fclose(out);
}

// A PLY of m (vcglib's exporter; the cut's boundary shows in MeshLab).
void WritePly(Mesh &m, const std::string &path) {
  if (vcg::tri::io::ExporterPLY<Mesh>::Save(m, path.c_str(), false) != 0) throw std::runtime_error("cannot write " + path);
}

std::map<std::string, std::string> Assignments(int argc, char **argv, int first) {
  std::map<std::string, std::string> values;
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    const std::size_t eq = a.find('=');
    if (eq == std::string::npos) throw Error("expected NAME=VALUE, got " + a);
    values[a.substr(0, eq)] = a.substr(eq + 1);
  }
  return values;
}

int Flag(int argc, char **argv, const char *name, int fallback) {
  for (int i = 0; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], name)) return std::atoi(argv[i + 1]);
  return fallback;
}

double FlagValue(int argc, char **argv, const char *name, double fallback) {
  for (int i = 0; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], name)) return std::atof(argv[i + 1]);
  return fallback;
}

Options OptionsFrom(int argc, char **argv) {
  Options o;
  o.alpha = FlagValue(argc, argv, "--alpha", o.alpha);
  o.anchorWeight = FlagValue(argc, argv, "--anchor-weight", o.anchorWeight);
  o.anchorRadius = FlagValue(argc, argv, "--anchor-radius", o.anchorRadius);
  o.threads = Flag(argc, argv, "--threads", 0);
  o.gridResolution = Flag(argc, argv, "--grid", o.gridResolution);
  o.steps = Flag(argc, argv, "--steps", o.steps);
  if (const char *align = StringFlag(argc, argv, "--align")) o.align = std::strcmp(align, "none") ? Align::CentreAndScale : Align::None;
  if (HasFlag(argc, argv, "--no-untangle")) o.untangle = false;  // the map before untangling (--save writes it so)
  for (int i = 0; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--solver")) {
      const std::string s = argv[i + 1];
      o.solver = s == "gs" ? VelocitySolver::Method::GaussSeidel
                 : s == "cg" ? VelocitySolver::Method::ConjugateGradient
                             : VelocitySolver::Method::Multigrid;
    }
  return o;
}

// Wall seconds of fn().
template <class Fn> double Wall(Fn &&fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Table 1 row n (1..4): its meshes and anchors, the map into result; the wall seconds of
// the map (ComputeMap), without the loading and bending of the meshes.
double MapRow(int n, int argc, char **argv, Options options, Result &result, double &strength) {
  const Row &row = kRows[n - 1];
  Mesh source, target;
  LoadMesh(DataMesh(row.mesh), source);
  RefineMidpoint(source, row.refinements);
  LoadMesh(DataMesh(row.mesh), target);
  RefineMidpoint(target, row.refinements);
  strength = FlagValue(argc, argv, "--deformation", row.deformation);
  for (Vertex &v : target.vert) v.P() = Bend(v.P(), source.bbox, strength);
  const std::vector<AnchorPair> anchors = FarthestPointAnchors(source, target, row.anchors);
  options.gridNodes = row.nodes;
  options.steps = 40;
  return Wall([&] { ComputeMap(source, target, anchors, options, result); });
}

} // namespace

int main(int argc, char **argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  try {
    if (command == "header") return std::printf("%s\n", Header().c_str()), 0;
    if (command == "parameters") return std::printf("%s", ParametersMarkdown().c_str()), 0;
    if (command == "mlx")
      return std::printf("<!DOCTYPE FilterScript>\n<FilterScript>\n%s</FilterScript>\n",
                         MlxFilter(Assignments(argc, argv, 2)).c_str()),
             0;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s row N | grid CELLS | shapes SOURCE TARGET [--save DIR] | map SOURCE TARGET [SOURCE.pp TARGET.pp] [--save DIR] [options] | header | "
                         "mlx [NAME=VALUE ...] | parameters\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[1];
  Options options = OptionsFrom(argc, argv);
  Mesh source, target;
  std::vector<AnchorPair> anchors;
  Result result;
  try {
    if (mode == "row") {
      const int n = std::atoi(argv[2]);
      double strength;
      MapRow(n, argc, argv, options, result, strength);
      const Row &row = kRows[n - 1];
      PrintRow(std::string("Table 1 row ") + argv[2] + (strength != row.deformation ? ", deformation " + std::to_string(strength).substr(0, 4) : ""),
               result.report, row.paperInt + row.paperVf + row.paperDef);
    } else if (mode == "load") {
      // The same map quiet, beside one busy process per core, and beside as many niced ones
      // (nice 10, as a background build in this session), with OpenMP's settings as the
      // environment leaves them (tests/bench/run unsets OMP_WAIT_POLICY): the team's loops
      // must not wait for a member the scheduler took off its core (parallel.h). The time is
      // the map's (ComputeMap), not the loading of its meshes. Beside one busy process per
      // core the team's fair share is one core, so the map on one thread, quiet, is the time
      // it can reach there; its ratio to the quiet time is the team's speed-up.
      // Rounds of the four, alternated, and their medians: this shared machine's speed drifts
      // by the minute (one round's ratio ranged 1.97-2.33 over a day with the same code).
      const int n = std::atoi(argv[2]);
      const int cores = int(sysconf(_SC_NPROCESSORS_ONLN));
      constexpr int kRounds = 3;
      double strength;
      std::vector<double> quiet, oneThread, busy[2];  // busy: nice 0, nice 10
      Options alone = options;
      alone.threads = 1;
      for (int round = 0; round < kRounds; ++round) {
        quiet.push_back(MapRow(n, argc, argv, options, result, strength));
        oneThread.push_back(MapRow(n, argc, argv, alone, result, strength));
        for (const int nice : {0, 10}) {
          const BusyProcesses load(cores, nice);
          busy[nice ? 1 : 0].push_back(MapRow(n, argc, argv, options, result, strength));
        }
        std::printf("load: round %d: %.2f s quiet (%.2f s on 1 thread), %.2f s beside %d busy processes at nice 0, "
                    "%.2f s at nice 10\n",
                    round + 1, quiet.back(), oneThread.back(), busy[0].back(), cores, busy[1].back());
      }
      auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
      };
      const double quietTime = median(quiet);
      std::printf("load: Table 1 row %d, the map %.2f s quiet (%d threads; medians of %d rounds), %.2f s on 1 thread "
                  "(%.2f times quiet)\n",
                  n, quietTime, result.report.threads, kRounds, median(oneThread), median(oneThread) / quietTime);
      for (const int nice : {0, 10})
        std::printf("load: Table 1 row %d, the map %.2f s beside %d busy processes at nice %d (%d threads): %.2f "
                    "times quiet\n",
                    n, median(busy[nice ? 1 : 0]), cores, nice, result.report.threads,
                    median(busy[nice ? 1 : 0]) / quietTime);
    } else if (mode == "grid") {
      // The grid of CELLS^3 nodes over the common box (grid_resolution CELLS would give
      // CELLS + 1 nodes on the longest axis and fewer across).
      MakeSphere(source, Point3(0, 0, 0), 1, 5);
      MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.4, 0.8, 0.9), 5);
      const int cells = std::atoi(argv[2]);
      options.gridNodes = vcg::Point3i(cells, cells, cells);
      options.align = Align::None;
      // The longest wall time between two calls of the progress callback (pipeline.h): the
      // GUI's bar moves and hears Cancel that often.
      auto last = std::chrono::steady_clock::now();
      double longest = 0;
      std::string from, previous, to;
      ComputeMap(source, target, anchors, options, result, [&](double, const std::string &stage) {
        const auto now = std::chrono::steady_clock::now();
        const double gap = std::chrono::duration<double>(now - last).count();
        if (gap > longest) longest = gap, from = previous, to = stage;
        last = now, previous = stage;
        return true;
      });
      PrintRow(std::string("grid ") + argv[2] + "^3", result.report, 0);
      std::printf("grid %s^3: longest time between two progress calls %.2f s (from '%s' to '%s')\n", argv[2], longest,
                  from.c_str(), to.c_str());
    } else if (mode == "vertices") {
      const int subdivisions = std::atoi(argv[2]);
      MakeSphere(source, Point3(0, 0, 0), 1, subdivisions);
      MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.4, 0.8, 0.9), 5);
      options.align = Align::None;
      ComputeMap(source, target, anchors, options, result);
      PrintRow(std::string("sphere, ") + argv[2] + " subdivisions", result.report, 0);
    } else if (mode == "soup") {
      // An STL-like input is welded on the pipeline's copy (input.h): the soup's time is the
      // welded mesh's plus the welding.
      MakeSphere(source, Point3(0, 0, 0), 1, std::atoi(argv[2]));
      MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
      Mesh soup;
      for (const Face &f : source.face) {
        auto v = vcg::tri::Allocator<Mesh>::AddVertices(soup, 3);
        for (int c = 0; c < 3; ++c) v[c].P() = f.cP(c);
        vcg::tri::Allocator<Mesh>::AddFace(soup, &*v, &*v + 1, &*v + 2);
      }
      const std::string faces = std::to_string(source.fn) + " faces";
      auto wall = [&](const Mesh &from) {  // the whole ComputeMap, the welding included
        const auto start = std::chrono::steady_clock::now();
        ComputeMap(from, target, anchors, options, result);
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      };
      const double welded = wall(source);
      PrintRow("sphere -> torus, " + faces + ", welded", result.report, 0);
      const double asSoup = wall(soup);
      PrintRow("sphere -> torus, " + faces + ", triangle soup", result.report, 0);
      std::printf("whole map, triangle soup / welded: %.2f s / %.2f s = %.2f\n", asSoup, welded, asSoup / welded);
    } else if (mode == "shapes") {
      // Two of tests/support/shapes.h's shapes (marching cubes at 64 cells, as the family
      // tests make them), default placement unless --align says otherwise: the report and
      // the family tests' line of figures.
      MakeShape(argv[2], source, 64);
      MakeShape(argv[3], target, 64);
      const auto start = std::chrono::steady_clock::now();
      // --stages: each stage's name on stderr as it starts, with the seconds since the start.
      const bool stages = HasFlag(argc, argv, "--stages");
      std::string last;
      ComputeMap(source, target, anchors, options, result, [&](double, const std::string &stage) {
        if (stages && stage != last)
          std::fprintf(stderr, "%8.2f s  %s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                       (last = stage).c_str());
        return true;
      });
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%s%s", result.report.ToText().c_str(),
                  Figures(argv[2], argv[3], options.gridResolution, target, result, seconds).line.c_str());
    } else if (mode == "map") {
      LoadMesh(argv[2], source);
      LoadMesh(argv[3], target);
      if (argc > 5 && argv[4][0] != '-') anchors = ReadAnchorPairs(argv[4], argv[5]);
      ComputeMap(source, target, anchors, options, result);
      std::printf("%s", result.report.ToText().c_str());
      if (const char *images = StringFlag(argc, argv, "--images")) WriteImages(source, result, images);
    } else {
      std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
      return 2;
    }
    if (const char *dir = StringFlag(argc, argv, "--save")) {  // DIR/cut.ply, DIR/mapped.ply, DIR/target.ply
      WritePly(result.cut, std::string(dir) + "/cut.ply");
      WritePly(result.mapped, std::string(dir) + "/mapped.ply");
      WritePly(target, std::string(dir) + "/target.ply");
    }
  } catch (const std::exception &e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
