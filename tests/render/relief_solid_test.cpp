// The relief as a printable solid (relief_solid.hpp): closed and manifold (every edge shared by
// exactly two triangles, wound opposite ways), of positive volume, as big as the canvas and
// as high as the paint; flat areas take few triangles while the volume stays within the
// allowed height error; and the files read back as the same closed solid.
#include "impasto/render/relief_solid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "impasto/render/render_painting.hpp"

namespace impasto::render {
namespace {

// 100 x 60 cells of 0.1 mm: a flat field with a dome of paint and a ridge at one edge.
HeightGrid study_heights(double flat_mm = 0.0) {
  HeightGrid g{100, 60, 0.1, {}};
  g.mm.resize(100 * 60);
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const double r = std::hypot(x - 40.0, y - 30.0);
      double h = flat_mm + (r < 20.0 ? 0.6 * (1.0 - (r / 20.0) * (r / 20.0)) : 0.0);
      if (x >= 95) h += 0.3 * std::sin(0.7 * y) + 0.3;
      g.mm[static_cast<std::size_t>(y * g.width + x)] = static_cast<float>(h);
    }
  }
  return g;
}

struct Closedness {
  bool manifold = true;  // every edge in two triangles, once each way
  std::string first_problem;
};

Closedness closedness(const SolidMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  Closedness c;
  for (const auto& [edge, count] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (count != 1 || back == directed.end() || back->second != 1) {
      c.manifold = false;
      c.first_problem = "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                        " used " + std::to_string(count) + " times this way, " +
                        std::to_string(back == directed.end() ? 0 : back->second) + " the other";
      return c;
    }
  }
  return c;
}

// The divergence theorem: the sum of the signed tetrahedra from the origin.
double volume_of(const SolidMesh& mesh) {
  double v = 0.0;
  for (const auto& t : mesh.triangles) {
    const auto &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    v += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
          double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
          double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
         6.0;
  }
  return v;
}

TEST(ReliefSolid, IsClosedAndAsBigAsTheCanvasAndThePaint) {
  const HeightGrid heights = study_heights();
  SolidOptions options;
  options.base_mm = 1.5;
  options.relief_scale = 2.0;
  const SolidMesh mesh = relief_solid(heights, options);
  const Closedness c = closedness(mesh);
  EXPECT_TRUE(c.manifold) << c.first_problem;
  EXPECT_GT(volume_of(mesh), 0.0) << "wound inside out";
  std::array<float, 3> low{1e9f, 1e9f, 1e9f}, high{-1e9f, -1e9f, -1e9f};
  for (const auto& p : mesh.vertices) {
    for (int i = 0; i < 3; ++i) {
      low[static_cast<std::size_t>(i)] = std::min(low[static_cast<std::size_t>(i)], p[i]);
      high[static_cast<std::size_t>(i)] = std::max(high[static_cast<std::size_t>(i)], p[i]);
    }
  }
  EXPECT_FLOAT_EQ(low[0], 0.0f);
  EXPECT_FLOAT_EQ(low[1], 0.0f);
  EXPECT_NEAR(high[0], 10.0f, 1e-5f);  // 100 cells of 0.1 mm
  EXPECT_NEAR(high[1], 6.0f, 1e-5f);
  EXPECT_FLOAT_EQ(low[2], -1.5f);  // the back, under a ground at 0
  // The highest corner: the dome's top (0.6 mm, corners average four cells) times two.
  const float top = *std::max_element(heights.mm.begin(), heights.mm.end());
  EXPECT_GT(high[2], 2.0f * top * 0.95f);
  EXPECT_LE(high[2], 2.0f * top + 1e-5f);
}

TEST(ReliefSolid, AFlatPaintingIsABoxOfFewTriangles) {
  const HeightGrid flat{64, 32, 0.25, std::vector<float>(64 * 32, 0.4f)};
  const SolidMesh mesh = relief_solid(flat, SolidOptions{});
  EXPECT_TRUE(closedness(mesh).manifold);
  // 16 x 8 mm, 0.4 mm of paint over a 2 mm back.
  EXPECT_NEAR(volume_of(mesh), 16.0 * 8.0 * 2.4, 1e-3);
  EXPECT_LT(mesh.triangles.size(), 200u) << "a flat top needs no fine grid";
}

// The volume under the top drawn through every corner (two triangles a cell), down to the
// back: what a mesh without simplification holds.
double full_grid_volume(const HeightGrid& cells, double base_mm) {
  const auto corner = [&](int x, int y) {
    double sum = 0.0;
    int count = 0;
    for (int cy = std::max(y - 1, 0); cy <= std::min(y, cells.height - 1); ++cy)
      for (int cx = std::max(x - 1, 0); cx <= std::min(x, cells.width - 1); ++cx, ++count)
        sum += cells.at(cx, cy);
    return sum / count;
  };
  double v = 0.0;
  for (int y = 0; y < cells.height; ++y) {
    for (int x = 0; x < cells.width; ++x) {  // two prisms of half a cell, over the diagonal a-c
      const double a = corner(x, y), b = corner(x + 1, y), c = corner(x + 1, y + 1),
                   d = corner(x, y + 1);
      v += 0.5 * cells.cell_mm * cells.cell_mm * ((a + b + c) / 3.0 + (a + c + d) / 3.0);
    }
  }
  return v + base_mm * cells.width * cells.height * cells.cell_mm * cells.cell_mm;
}

// Flat areas take few triangles; the error allowed bounds how far the top may sag or bulge,
// so the volume moves by at most that error times the area.
TEST(ReliefSolid, SimplifiesFlatAreasWithinTheErrorAsked) {
  const HeightGrid heights = study_heights(0.1);
  SolidOptions exact, coarse;
  exact.max_error_mm = 0.0;
  coarse.max_error_mm = 0.02;
  const SolidMesh full = relief_solid(heights, exact);
  const SolidMesh simple = relief_solid(heights, coarse);
  const double reference = full_grid_volume(heights, exact.base_mm);
  const double area = 10.0 * 6.0;
  EXPECT_NEAR(volume_of(full), reference, 1e-5 * reference) << "error 0 keeps the surface";
  EXPECT_TRUE(closedness(simple).manifold) << closedness(simple).first_problem;
  EXPECT_LT(simple.triangles.size(), 2u * 100u * 60u / 4u) << "a quarter of the full grid's";
  EXPECT_LT(simple.triangles.size(), full.triangles.size());
  EXPECT_LE(std::abs(volume_of(simple) - reference), coarse.max_error_mm * area);
  std::cout << "[ solid ] " << full.triangles.size()
            << " triangles exact (a full grid: " << 2 * 100 * 60 << "), " << simple.triangles.size()
            << " within 0.02 mm; volume " << reference << " / " << volume_of(full) << " / "
            << volume_of(simple) << " mm^3\n";
}

TEST(ReliefSolid, ATriangleBudgetRaisesTheErrorUntilTheMeshFits) {
  const HeightGrid heights = study_heights(0.1);
  SolidOptions exact;
  exact.max_error_mm = 0.0;
  const SolidMesh full = relief_solid(heights, exact);
  EXPECT_EQ(full.max_error_mm, 0.0);
  for (const std::size_t budget : {std::size_t{2000}, std::size_t{500}}) {
    SolidOptions limited = exact;
    limited.max_triangles = budget;
    const SolidMesh mesh = relief_solid(heights, limited);
    EXPECT_LE(mesh.triangles.size(), budget);
    EXPECT_GT(mesh.triangles.size(), budget / 2) << "the budget is used, not squandered";
    EXPECT_GT(mesh.max_error_mm, 0.0);
    EXPECT_TRUE(closedness(mesh).manifold) << closedness(mesh).first_problem;
    // The same mesh as asking for that error outright.
    SolidOptions by_error = exact;
    by_error.max_error_mm = mesh.max_error_mm;
    EXPECT_EQ(relief_solid(heights, by_error).triangles.size(), mesh.triangles.size());
  }
  // A budget below the fewest a closed solid can have gives the fewest.
  SolidOptions tiny = exact;
  tiny.max_triangles = 4;
  const SolidMesh fewest = relief_solid(heights, tiny);
  EXPECT_GT(fewest.triangles.size(), 4u);
  EXPECT_TRUE(closedness(fewest).manifold);
  // A budget the asked error already meets changes nothing.
  SolidOptions roomy = exact;
  roomy.max_triangles = full.triangles.size();
  EXPECT_EQ(relief_solid(heights, roomy).triangles.size(), full.triangles.size());
}

TEST(ReliefSolid, RefusesAnEmptyGridAndBadOptions) {
  EXPECT_THROW(relief_solid(HeightGrid{}, SolidOptions{}), std::invalid_argument);
  SolidOptions no_base;
  no_base.base_mm = 0.0;
  EXPECT_THROW(relief_solid(study_heights(), no_base), std::invalid_argument);
  SolidOptions nan_error;
  nan_error.max_error_mm = std::nan("");
  EXPECT_THROW(relief_solid(study_heights(), nan_error), std::invalid_argument);
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// A binary STL read back as a slicer reads it: triangles of coordinates, vertices merged where
// their coordinates are equal.
SolidMesh read_stl(const std::string& bytes) {
  SolidMesh mesh;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(bytes.size(), 84u + 50u * count);
  std::map<std::array<float, 3>, std::uint32_t> index;
  for (std::uint32_t t = 0; t < count; ++t) {
    std::array<std::uint32_t, 3> tri{};
    for (int v = 0; v < 3; ++v) {
      std::array<float, 3> p{};
      std::memcpy(p.data(), bytes.data() + 84 + 50 * t + 12 + 12 * v, 12);
      const auto [it, added] = index.try_emplace(p, static_cast<std::uint32_t>(index.size()));
      if (added) mesh.vertices.push_back(p);
      tri[static_cast<std::size_t>(v)] = it->second;
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

TEST(ReliefSolid, FilesReadBackAsTheSameClosedSolid) {
  SolidMesh mesh = relief_solid(study_heights(), SolidOptions{});
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("impasto_relief_solid_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  write_solid(dir / "a.stl", mesh);
  const SolidMesh stl = read_stl(read_bytes(dir / "a.stl"));
  EXPECT_EQ(stl.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(stl.vertices.size(), mesh.vertices.size());
  EXPECT_TRUE(closedness(stl).manifold) << closedness(stl).first_problem;
  EXPECT_NEAR(volume_of(stl), volume_of(mesh), 1e-6 * volume_of(mesh));

  Image red{100, 60, std::vector<float>(3 * 100 * 60, 0.0f)};
  for (std::size_t i = 0; i < red.rgb.size(); i += 3) red.rgb[i] = 1.0f;
  colour_solid(mesh, red, 0.1);
  write_solid(dir / "a.ply", mesh);
  const std::string ply = read_bytes(dir / "a.ply");
  const std::string header = ply.substr(0, ply.find("end_header\n") + 11);
  EXPECT_NE(header.find("element vertex " + std::to_string(mesh.vertices.size())),
            std::string::npos);
  EXPECT_NE(header.find("property uchar red"), std::string::npos);
  EXPECT_EQ(ply.size(), header.size() + mesh.vertices.size() * 15 + mesh.triangles.size() * 13);
  std::uint8_t first_red = 0;
  std::memcpy(&first_red, ply.data() + header.size() + 12, 1);
  EXPECT_EQ(first_red, 255);

  write_solid(dir / "a.obj", mesh);
  std::istringstream obj(read_bytes(dir / "a.obj"));
  std::size_t v = 0, f = 0;
  for (std::string line; std::getline(obj, line);) {
    v += line.rfind("v ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, mesh.vertices.size());
  EXPECT_EQ(f, mesh.triangles.size());
  EXPECT_THROW(write_solid(dir / "a.gltf", mesh), std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace impasto::render
