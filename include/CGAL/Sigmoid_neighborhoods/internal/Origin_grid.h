// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIGIN_GRID_H
#define CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIGIN_GRID_H

#include <stdexcept>
#include <CGAL/Sigmoid_neighborhoods/internal/Neighbor.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/Classification/compressed_float.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace internal {

// CGAL's planimetric grids (CGAL::Classification::Planimetric_grid) anchored at the origin: the
// first scale's cell of a point is (floor(x / r), floor(y / r)), a coarser scale's merges 2 x 2
// cells of the finer one. CGAL anchors the first at the point set's bounding box, so that a tile
// and the union of tiles place the same point in different cells; here the cells do not depend on
// the other points, and a tile read with a wide enough halo gets the union's features.
// Cells are stored over the points' extent, its first cell a multiple of the coarsest scale's.
class Origin_grid
{
public:
  Origin_grid(const std::vector<Double_point>& points, float resolution, unsigned int scales)
    : m_points(&points), m_resolution(resolution), m_scales((std::max)(1u, scales))
  {
    const std::size_t n = points.size();
    m_x.resize(n);
    m_y.resize(n);
    if(n == 0)
      return;
    std::int64_t min_x = (std::numeric_limits<std::int64_t>::max)(), min_y = min_x;
    std::int64_t max_x = (std::numeric_limits<std::int64_t>::min)(), max_y = max_x;
    std::vector<std::int64_t> cell_x(n), cell_y(n);
    // beyond 2^52 cells from the origin, cells would not hold distinct coordinates anyway
    const double limit = 4503599627370496.;
    for(std::size_t i = 0; i < n; ++i)
    {
      // as CGAL divides: a double by the float resolution
      const double fx = std::floor(points[i].x() / resolution), fy = std::floor(points[i].y() / resolution);
      if(!(std::abs(fx) < limit && std::abs(fy) < limit))
        throw std::invalid_argument("a point " + std::to_string(i) + " lies too far from the origin for grids of " +
                          std::to_string(resolution) + " m");
      cell_x[i] = std::int64_t(fx);
      cell_y[i] = std::int64_t(fy);
      min_x = (std::min)(min_x, cell_x[i]);
      max_x = (std::max)(max_x, cell_x[i]);
      min_y = (std::min)(min_y, cell_y[i]);
      max_y = (std::max)(max_y, cell_y[i]);
    }
    // the first cell a multiple of the coarsest cell (an arithmetic shift rounds down)
    const unsigned int top = m_scales - 1;
    m_base_x = (min_x >> top) * (std::int64_t(1) << top);
    m_base_y = (min_y >> top) * (std::int64_t(1) << top);
    const std::uint64_t width = std::uint64_t(max_x - m_base_x) + 1, height = std::uint64_t(max_y - m_base_y) + 1;
    // CGAL's grids are as dense; refuse what would not fit rather than fail allocating
    const std::uint64_t largest = 16 * std::uint64_t(n) + (std::uint64_t(1) << 24);
    if(width > largest || height > largest || width * height > largest)
      throw std::invalid_argument("the points span " + std::to_string(width) + " x " + std::to_string(height) +
                        " grid cells of " + std::to_string(resolution) +
                        " m, too many for their number: split the point set in tiles");
    m_width = std::size_t(width);
    m_height = std::size_t(height);
    m_begin.assign(m_width * m_height + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      m_x[i] = std::uint32_t(cell_x[i] - m_base_x);
      m_y[i] = std::uint32_t(cell_y[i] - m_base_y);
      ++m_begin[cell(i) + 1];
    }
    for(std::size_t c = 0; c < m_width * m_height; ++c)
      m_begin[c + 1] += m_begin[c];
    // each cell's points in index order, the order of CGAL's grid
    m_indices.resize(n);
    std::vector<std::uint32_t> next(m_begin.begin(), m_begin.end() - 1);
    for(std::size_t i = 0; i < n; ++i)
      m_indices[next[cell(i)]++] = std::uint32_t(i);
  }

  unsigned int scales() const { return m_scales; }
  // the resolution of scale s, doubled per scale in float as CGAL's grids double it
  float resolution(unsigned int s) const
  {
    float r = m_resolution;
    for(unsigned int l = 0; l < s; ++l)
      r = r * 2;
    return r;
  }
  std::size_t width(unsigned int s) const { return ((m_width - 1) >> s) + 1; }
  std::size_t height(unsigned int s) const { return ((m_height - 1) >> s) + 1; }
  std::size_t x(std::size_t i, unsigned int s) const { return m_x[i] >> s; }
  std::size_t y(std::size_t i, unsigned int s) const { return m_y[i] >> s; }

  // Calls f(i) for the points of cell (x, y) of scale s in the order of CGAL's grid iterator: the
  // first scale's cells x-major, each cell's points in index order.
  template <typename F>
  void for_each_point(unsigned int s, std::size_t x, std::size_t y, const F& f) const
  {
    const std::size_t x_end = (std::min)((x + 1) << s, m_width), y_end = (std::min)((y + 1) << s, m_height);
    for(std::size_t fx = x << s; fx < x_end; ++fx)
      for(std::size_t fy = y << s; fy < y_end; ++fy)
      {
        const std::size_t c = fx * m_height + fy;
        for(std::uint32_t e = m_begin[c]; e < m_begin[c + 1]; ++e)
          f(m_indices[e]);
      }
  }

  const std::vector<Double_point>& points() const { return *m_points; }

private:
  std::size_t cell(std::size_t i) const { return std::size_t(m_x[i]) * m_height + m_y[i]; }

  const std::vector<Double_point>* m_points;
  float m_resolution;
  unsigned int m_scales;
  std::int64_t m_base_x = 0, m_base_y = 0;
  std::size_t m_width = 1, m_height = 1;
  std::vector<std::uint32_t> m_x, m_y;   // each point's first-scale cell, from the first stored one
  std::vector<std::uint32_t> m_begin;   // the first-scale cells' points, x-major: [m_begin[c], m_begin[c + 1])
  std::vector<std::uint32_t> m_indices;
};

// The features of CGAL's generator on one scale of a grid, as CGAL's Feature::Vertical_dispersion,
// Elevation, Height_below, Height_above and Vertical_range compute them, with their radii
// (`radius_neighbors`, `radius_dtm`) and their float arithmetic, one value per point. Two choices
// differ from CGAL's: the elevation's terrain model is kept in float (CGAL stores it in 256 steps
// of the whole set's height range, which a tile does not know), and the height above a cell is
// float(top - z) in double, the form CGAL uses when its grid has more cells than points.
struct Origin_grid_features
{
  std::vector<float> dispersion, elevation, height_below, height_above, vertical_range;
};

template <typename ConcurrencyTag>
Origin_grid_features origin_grid_features(const Origin_grid& grid, unsigned int s, float radius_neighbors,
                                          float radius_dtm, unsigned int threads)
{
  using CGAL::Classification::compress_float;
  using CGAL::Classification::compressed_float;
  using CGAL::Classification::decompress_float;
  const std::vector<Double_point>& points = grid.points();
  const std::size_t n = points.size(), width = grid.width(s), height = grid.height(s);
  const float resolution = grid.resolution(s);
  const auto no_scratch = [] { return 0; };

  // per cell: its points' lowest and highest z and their mean, in CGAL's order and float
  std::vector<std::uint32_t> count(width * height, 0);
  std::vector<float> low(width * height), high(width * height), mean(width * height, 0.f);
  for_each_index<ConcurrencyTag>(width, threads, no_scratch, [&](std::size_t x, int) {
    for(std::size_t y = 0; y < height; ++y)
    {
      const std::size_t c = x * height + y;
      float z_min = (std::numeric_limits<float>::max)(), z_max = -(std::numeric_limits<float>::max)(), sum = 0.f;
      std::uint32_t nb = 0;
      grid.for_each_point(s, x, y, [&](std::uint32_t i) {
        const float z = float(points[i].z());
        z_min = (std::min)(z_min, z);
        z_max = (std::max)(z_max, z);
        sum += z;
        ++nb;
      });
      count[c] = nb;
      low[c] = z_min;
      high[c] = z_max;
      if(nb > 0)
        mean[c] = sum / float(nb);
    }
  }, 1);

  Origin_grid_features out;
  out.dispersion.resize(n);
  out.elevation.resize(n);
  out.height_below.resize(n);
  out.height_above.resize(n);
  out.vertical_range.resize(n);

  // Vertical dispersion: the share of empty vertical bins among the cells near a cell. CGAL's
  // window tests (float)(k - i) of unsigned cells, so that only k >= i and l >= j pass; kept.
  std::vector<compressed_float> dispersion(width * height, compressed_float(0));
  {
    const std::size_t square = (std::size_t)(0.5 * radius_neighbors / resolution) + 1;
    float bound = (float)0.5 * radius_neighbors / resolution;
    bound = bound * bound;
    for_each_index<ConcurrencyTag>(width, threads, [] { return std::vector<char>(); },
                                   [&](std::size_t i, std::vector<char>& occupy) {
      const std::size_t i_end = (std::min)(width - 1, i + square);
      for(std::size_t j = 0; j < height; ++j)
      {
        if(count[i * height + j] == 0)
          continue;
        const std::size_t j_end = (std::min)(height - 1, j + square);
        auto in_window = [&](std::size_t k, std::size_t l) {
          const float dx = (float)(k - i), dy = (float)(l - j);
          return dx * dx + dy * dy <= bound && count[k * height + l] > 0;
        };
        float z_min = (std::numeric_limits<float>::max)(), z_max = -(std::numeric_limits<float>::max)();
        for(std::size_t k = i; k <= i_end; ++k)
          for(std::size_t l = j; l <= j_end; ++l)
            if(in_window(k, l))
            {
              z_min = (std::min)(z_min, low[k * height + l]);
              z_max = (std::max)(z_max, high[k * height + l]);
            }
        occupy.assign(1 + (std::size_t)((z_max - z_min) / resolution), 0);
        for(std::size_t k = i; k <= i_end; ++k)
          for(std::size_t l = j; l <= j_end; ++l)
            if(in_window(k, l))
              grid.for_each_point(s, k, l, [&](std::uint32_t p) {
                occupy[(std::size_t)((float(points[p].z()) - z_min) / resolution)] = 1;
              });
        std::size_t occupied = 0;
        for(char o : occupy)
          occupied += std::size_t(o);
        dispersion[i * height + j] = compress_float(1.f - (occupied / (float)(occupy.size())));
      }
    }, 1);
  }

  // Elevation: a terrain model, the 10th percentile of the cells' mean heights along x, then of
  // those along y, over `square` cells on each side (empty cells and means of exactly 0 skipped).
  std::vector<float> terrain(width * height, 0.f);
  {
    const std::size_t square = (std::size_t)(0.5 * radius_dtm / resolution) + 1;
    std::vector<float> along_x(width * height, 0.f);
    for_each_index<ConcurrencyTag>(width, threads, [] { return std::vector<float>(); },
                                   [&](std::size_t i, std::vector<float>& z) {
      const std::size_t k_begin = i < square ? 0 : i - square, k_end = (std::min)(width - 1, i + square);
      for(std::size_t j = 0; j < height; ++j)
      {
        if(count[i * height + j] == 0)
          continue;
        z.clear();
        for(std::size_t k = k_begin; k <= k_end; ++k)
          if(mean[k * height + j] != 0.f)
            z.push_back(mean[k * height + j]);
        if(z.empty())
          continue;
        std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(z.size() / 10), z.end());
        along_x[i * height + j] = z[z.size() / 10];
      }
    }, 1);
    for_each_index<ConcurrencyTag>(width, threads, [] { return std::vector<float>(); },
                                   [&](std::size_t i, std::vector<float>& z) {
      for(std::size_t j = 0; j < height; ++j)
      {
        if(count[i * height + j] == 0)
          continue;
        const std::size_t l_begin = j < square ? 0 : j - square, l_end = (std::min)(height - 1, j + square);
        z.clear();
        for(std::size_t l = l_begin; l <= l_end; ++l)
          if(along_x[i * height + l] != 0.f)
            z.push_back(along_x[i * height + l]);
        if(z.empty())
          continue;
        std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(z.size() / 10), z.end());
        terrain[i * height + j] = z[z.size() / 10];
      }
    }, 1);
  }

  for_each_index<ConcurrencyTag>(n, threads, no_scratch, [&](std::size_t i, int) {
    const std::size_t c = grid.x(i, s) * height + grid.y(i, s);
    const double z = points[i].z();
    out.dispersion[i] = decompress_float(dispersion[c]);
    out.elevation[i] = (float)(z - terrain[c]);
    out.height_below[i] = float(z - low[c]);
    out.height_above[i] = float(high[c] - z);
    out.vertical_range[i] = high[c] - low[c];
  }, 4096);
  return out;
}

// How far (in x and y) from a point the cells that its grid features read can reach: for every
// scale, the farther window of the two (dispersion, elevation) plus the point's own cell.
inline double origin_grid_reach(float resolution, unsigned int scales, float first_voxel)
{
  double reach = 0.;
  float r = resolution, voxel = first_voxel;
  for(unsigned int s = 0; s < (std::max)(1u, scales); ++s)
  {
    const float radius_neighbors = voxel * 3, radius_dtm = voxel * 10;
    const std::size_t square = (std::max)((std::size_t)(0.5 * radius_neighbors / r) + 1,
                                          (std::size_t)(0.5 * radius_dtm / r) + 1);
    reach = (std::max)(reach, double(square + 1) * double(r));
    r = r * 2;
    voxel = voxel * 2;
  }
  return reach;
}

} // namespace internal
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_INTERNAL_ORIGIN_GRID_H
