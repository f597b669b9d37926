// Fields and the mesh type start from zero, whatever memory they are given.
//
// vcg::Point3 and vcg::TexCoord2 leave their coordinates uninitialised when default
// constructed. Inside MeshLab (a long-lived process, its stack and heap full of old
// values) that made Field<Point3>::Sample add V onto garbage (the tracker lost points and
// surgery cut spot -> cow, a same-genus pair) and made a target without texture
// coordinates look textured. These tests dirty the stack and the heap first.
#include "core/field.h"
#include "core/mesh.h"
#include "core/transfer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace eulermap {
namespace {

// Fills a stretch of the stack below the caller with a NaN pattern.
__attribute__((noinline)) void DirtyStack() {
  volatile unsigned char junk[1 << 14];
  for (std::size_t n = 0; n < sizeof junk; ++n) junk[n] = 0x7f;
}

__attribute__((noinline)) Point3 SampleAfterDirtyStack(const VectorField &v, const Point3 &p) {
  DirtyStack();
  return v.Sample(p);
}

TEST(Field, VectorSampleOfAConstantFieldIsThatConstant) {
  const Grid grid = Grid::Enclosing(Box3(Point3(0, 0, 0), Point3(1, 1, 1)), 4);
  const Point3 c(0.25, -1.5, 2);
  const VectorField v(grid, c);
  for (const Point3 &p : {Point3(0.5, 0.5, 0.5), Point3(0.1, 0.9, 0.3), Point3(2, -1, 0.5)}) {
    const Point3 s = SampleAfterDirtyStack(v, p);
    EXPECT_NEAR(vcg::Distance(s, c), 0, 1e-12) << "at " << p[0] << " " << p[1] << " " << p[2];
  }
}

TEST(Mesh, TextureCoordinatesStartAtZero) {
  // Leave freed heap blocks full of a non-zero pattern, then allocate the mesh.
  for (int round = 0; round < 4; ++round) {
    std::unique_ptr<unsigned char[]> junk(new unsigned char[1 << 20]);
    std::memset(junk.get(), 0x5a, 1 << 20);
  }
  Mesh m;
  vcg::tri::Allocator<Mesh>::AddVertices(m, 3000);
  vcg::tri::Allocator<Mesh>::AddFaces(m, 6000);
  for (Face &f : m.face)
    for (int c = 0; c < 3; ++c) f.V(c) = &m.vert[c];
  int nonZero = 0;
  for (const Vertex &v : m.vert) nonZero += v.cT().P() != vcg::Point2d(0, 0);
  for (const Face &f : m.face)
    for (int c = 0; c < 3; ++c) nonZero += f.cWT(c).P() != vcg::Point2d(0, 0) || f.cWT(c).N() != 0;
  EXPECT_EQ(nonZero, 0);
  EXPECT_EQ(DetectTexCoords(m), TexCoordKind::None);
}

} // namespace
} // namespace eulermap
