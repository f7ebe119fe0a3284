// The mesh the MeshLab 2020.09 adapter tests run on, and a snapshot of every per-element value
// a filter might change, to check what a run wrote and what it left alone.
#pragma once

#include <common/ml_mesh_type.h>
#include <vcg/complex/allocate.h>

#include <cmath>
#include <vector>

namespace qdml::test {

// An open cylinder (radius 1, height 2, `around` x `along` quads split into triangles) with one
// smooth bump of height bump_height (0: exactly developable), so the filter has curvature to
// remove. Face quality = 0, face colours and wedge texture coordinates set and distinct.
inline void make_bumpy_cylinder(CMeshO& m, int around = 24, int along = 12,
                                double bump_height = 0.08) {
  m.Clear();
  m.face.EnableQuality();
  m.face.EnableColor();
  m.face.EnableWedgeTexCoord();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, static_cast<size_t>(around * (along + 1)));
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i, ++vi) {
      const double a = 2 * std::acos(-1.0) * i / around;
      const double h = 2.0 * j / along;
      const double bump = bump_height * std::exp(-((a - 1) * (a - 1) + (h - 1) * (h - 1)) / 0.1);
      vi->P() =
          CMeshO::CoordType(static_cast<float>((1 + bump) * std::cos(a)),
                            static_cast<float>((1 + bump) * std::sin(a)), static_cast<float>(h));
    }
  const auto index = [around](int i, int j) {
    return static_cast<size_t>(j * around + (i % around));
  };
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[index(i, j)], &m.vert[index(i + 1, j)],
                                           &m.vert[index(i + 1, j + 1)]);
      vcg::tri::Allocator<CMeshO>::AddFace(m, &m.vert[index(i, j)], &m.vert[index(i + 1, j + 1)],
                                           &m.vert[index(i, j + 1)]);
    }
  for (size_t f = 0; f < m.face.size(); ++f) {
    m.face[f].Q() = 0;
    m.face[f].C() = vcg::Color4b(static_cast<unsigned char>(f % 251), 7, 9, 255);
    for (int k = 0; k < 3; ++k)
      m.face[f].WT(k).U() = static_cast<float>(f) + 0.25f * static_cast<float>(k);
  }
}

struct Snapshot {
  std::vector<CMeshO::CoordType> positions;
  std::vector<float> quality;
  std::vector<vcg::Color4b> colours;
  std::vector<int> vertex_flags;
  std::vector<float> face_quality;
  std::vector<vcg::Color4b> face_colours;
  std::vector<float> texcoords;
  std::vector<int> face_flags;
};

inline Snapshot snapshot(const CMeshO& m) {
  Snapshot s;
  for (const auto& v : m.vert) {
    s.positions.push_back(v.cP());
    s.quality.push_back(v.cQ());
    s.colours.push_back(v.cC());
    s.vertex_flags.push_back(v.cFlags());
  }
  for (const auto& f : m.face) {
    s.face_quality.push_back(f.cQ());
    s.face_colours.push_back(f.cC());
    for (int k = 0; k < 3; ++k) s.texcoords.push_back(f.cWT(k).U());
    s.face_flags.push_back(f.cFlags());
  }
  return s;
}

}  // namespace qdml::test
