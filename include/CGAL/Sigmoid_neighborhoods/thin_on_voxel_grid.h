// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_THIN_ON_VOXEL_GRID_H
#define CGAL_SIGMOID_NEIGHBORHOODS_THIN_ON_VOXEL_GRID_H

#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Oriented_points.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  a point set thinned on a voxel grid: one representative per non-empty cell, and for every point
  the representative nearest to it (`thin_on_voxel_grid()`).
*/
struct Voxel_thinning
{
  double cell_size = 0.; ///< the side of the cubic cells
  /// the representatives: indices of points, one per non-empty cell, ascending
  std::vector<std::uint32_t> representatives;
  /// per point, the position in `representatives` of its nearest representative
  std::vector<std::uint32_t> nearest_representative;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

typedef std::array<std::int64_t, 3> Voxel;

// The non-empty cells and a point index each, in one flat array probed linearly: the nearest-
// representative pass looks up about 27 cells per point, where std::unordered_map's chasing of nodes
// took half of a pyramid's time.
class Voxel_table
{
public:
  static constexpr std::uint32_t EMPTY = 0xFFFFFFFFu; // no point index (there are fewer than 2^32 - 1)

  Voxel_table() { rehash(16); }

  // the value of cell v, `value` inserted when v is new; the reference is valid until the next insertion
  std::uint32_t& find_or_insert(const Voxel& v, std::uint32_t value)
  {
    if(2 * (m_size + 1) > m_keys.size())
      rehash(2 * m_keys.size());
    std::size_t s = slot(v);
    for(; m_values[s] != EMPTY; s = (s + 1) & m_mask)
      if(m_keys[s] == v)
        return m_values[s];
    m_keys[s] = v;
    m_values[s] = value;
    ++m_size;
    return m_values[s];
  }

  // the value of cell v, EMPTY when v is empty
  std::uint32_t find(const Voxel& v) const
  {
    for(std::size_t s = slot(v); m_values[s] != EMPTY; s = (s + 1) & m_mask)
      if(m_keys[s] == v)
        return m_values[s];
    return EMPTY;
  }

  // the values, in no particular order
  template <typename Function>
  void for_each_value(const Function& f) const
  {
    for(std::uint32_t value : m_values)
      if(value != EMPTY)
        f(value);
  }

private:
  std::size_t slot(const Voxel& v) const
  {
    std::uint64_t h = std::uint64_t(v[0]) * 0x9E3779B97F4A7C15ull;
    h = (h ^ std::uint64_t(v[1])) * 0xC2B2AE3D27D4EB4Full;
    h = (h ^ std::uint64_t(v[2])) * 0x9E3779B97F4A7C15ull;
    return std::size_t(h >> m_shift); // the high bits, the best mixed
  }

  void rehash(std::size_t capacity)
  {
    std::vector<Voxel> keys(capacity);
    std::vector<std::uint32_t> values(capacity, EMPTY);
    keys.swap(m_keys);
    values.swap(m_values);
    m_mask = capacity - 1;
    m_shift = 64;
    for(std::size_t c = capacity; c > 1; c /= 2)
      --m_shift;
    for(std::size_t s = 0; s < keys.size(); ++s)
      if(values[s] != EMPTY)
      {
        std::size_t t = slot(keys[s]);
        while(m_values[t] != EMPTY)
          t = (t + 1) & m_mask;
        m_keys[t] = keys[s];
        m_values[t] = values[s];
      }
  }

  std::vector<Voxel> m_keys;
  std::vector<std::uint32_t> m_values;
  std::size_t m_size = 0, m_mask = 0;
  int m_shift = 64;
};

inline Voxel voxel_of(const Double_point& p, double cell_size, std::size_t i)
{
  const double largest_index = 9.2e18; // below 2^63, with room for the neighbor cells' offsets
  const double c[3] = {std::floor(p.x() / cell_size), std::floor(p.y() / cell_size), std::floor(p.z() / cell_size)};
  for(double v : c)
    if(!(std::abs(v) < largest_index))
      throw std::invalid_argument("point " + std::to_string(i) + " lies beyond the voxels' 64-bit range");
  return {std::int64_t(c[0]), std::int64_t(c[1]), std::int64_t(c[2])};
}

inline double squared_distance_to_centre(const Double_point& p, const Voxel& v, double cell_size)
{
  const double dx = p.x() - (double(v[0]) + 0.5) * cell_size, dy = p.y() - (double(v[1]) + 0.5) * cell_size,
               dz = p.z() - (double(v[2]) + 0.5) * cell_size;
  return dx * dx + dy * dy + dz * dz;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgSigmoidNeighborhoodsRef
  \brief thins `points` on a grid of cubic cells of side `cell_size`: each non-empty cell keeps one
  representative, and every point is given its nearest representative.

  The cells are `[i c, (i + 1) c) x [j c, (j + 1) c) x [l c, (l + 1) c)` for integers `i`, `j`, `l`:
  anchored at the origin, as the cells of `compute_height_features()`, so that adjacent tiles of one
  survey get the cells of their union. A cell's representative is its point nearest to the cell's
  centre, ties to the smallest index: a rule that does not depend on the order of the points (bar
  exact ties), unlike "the first point of the cell", and keeps the representatives near a regular
  grid, so that a level's neighborhoods have about the same extent at any density above one point
  per cell. The nearest representative of a point is its nearest by Euclidean distance, ties to the
  smallest index (its own when the point is a representative): the mapping of Hackel et al. (2016),
  which, unlike "its cell's representative", never gives a point near a cell's side the features of
  a representative farther away than another cell's. The result is the same for any number of threads.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
  \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
  \tparam NamedParameters a sequence of named parameters

  \param points the input points
  \param cell_size the side of the cells, in the unit of the coordinates
  \param np optional: `point_map` (CGAL's) and `number_of_threads`

  \pre `cell_size` positive and finite; finite coordinates; fewer than `2^32` points; every cell
       index fits in 63 bits (otherwise `std::invalid_argument`)
*/
template <typename ConcurrencyTag, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
#ifdef DOXYGEN_RUNNING
Voxel_thinning
#else
std::enable_if_t<internal::is_range<PointRange>::value, Voxel_thinning>
#endif
thin_on_voxel_grid(const PointRange& points, double cell_size, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, CGAL_NP_CLASS> NP_helper;
  if(!(cell_size > 0.) || !std::isfinite(cell_size))
    throw std::invalid_argument("the cell size must be positive and finite, got " + std::to_string(cell_size));
  const unsigned int threads = internal::kernel_threads<ConcurrencyTag>(internal::number_of_threads(np));
  const std::vector<internal::Double_point> copy =
    internal::checked_points(points, NP_helper::get_const_point_map(points, np), threads);
  if(copy.size() > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw std::invalid_argument("thin_on_voxel_grid(): more than 2^32 - 1 points");
  const std::size_t n = copy.size();
  std::vector<internal::Voxel> voxels(n);
  // on the threads; a point beyond the voxels' range is named by a pass in order, the first
  std::atomic<bool> in_range(true);
  internal::for_each_index<ConcurrencyTag>(n, threads, [] { return 0; }, [&](std::size_t i, int&) {
    try
    {
      voxels[i] = internal::voxel_of(copy[i], cell_size, i);
    }
    catch(const std::invalid_argument&)
    {
      in_range.store(false, std::memory_order_relaxed);
    }
  }, 4096);
  if(!in_range.load())
    for(std::size_t i = 0; i < n; ++i)
      voxels[i] = internal::voxel_of(copy[i], cell_size, i);

  // each cell's point nearest to its centre; visited in index order, so a tie keeps the smaller index
  internal::Voxel_table chosen;
  for(std::size_t i = 0; i < n; ++i)
  {
    std::uint32_t& best = chosen.find_or_insert(voxels[i], std::uint32_t(i));
    if(best != i && internal::squared_distance_to_centre(copy[i], voxels[i], cell_size) <
                             internal::squared_distance_to_centre(copy[best], voxels[best], cell_size))
      best = std::uint32_t(i);
  }
  Voxel_thinning result;
  result.cell_size = cell_size;
  std::vector<std::uint32_t> position(n, 0); // of each representative in `representatives`
  std::vector<bool> is_representative(n, false);
  chosen.for_each_value([&](std::uint32_t i) { is_representative[i] = true; });
  for(std::size_t i = 0; i < n; ++i)
    if(is_representative[i])
    {
      position[i] = std::uint32_t(result.representatives.size());
      result.representatives.push_back(std::uint32_t(i));
    }

  // The own cell's representative lies within the cell's diagonal sqrt(3) c < 2 c, and a point of a
  // cell three steps away in any axis lies farther than 2 c: the nearest is in the 5 x 5 x 5 block.
  // A cell is skipped when its box lies farther than the best so far; the slack covers the rounding
  // of the box's sides, so that skipping never changes the result.
  result.nearest_representative.assign(n, 0);
  internal::for_each_index<ConcurrencyTag>(
    n, threads, [] { return 0; },
    [&](std::size_t i, int&) {
      const internal::Double_point& p = copy[i];
      const internal::Voxel& v = voxels[i];
      std::uint32_t best = chosen.find(v);
      auto squared_distance = [&p](const internal::Double_point& q) {
        const double dx = q.x() - p.x(), dy = q.y() - p.y(), dz = q.z() - p.z();
        return dx * dx + dy * dy + dz * dz;
      };
      double best_distance = squared_distance(copy[best]);
      const double slack = 1e-7 * cell_size;
      const double coordinates[3] = {p.x(), p.y(), p.z()};
      // per axis and offset -2 ... 2, the squared gap from p to the cells' slab, less the slack: a
      // cell's gap to p is the sum of its three, and whole slabs are skipped at once
      double slab_gap[3][5];
      for(int axis = 0; axis < 3; ++axis)
        for(int offset = -2; offset <= 2; ++offset)
        {
          double d = 0.;
          if(offset > 0)
            d = double(v[axis] + offset) * cell_size - coordinates[axis];
          else if(offset < 0)
            d = coordinates[axis] - double(v[axis] + offset + 1) * cell_size;
          d -= slack;
          slab_gap[axis][offset + 2] = d > 0. ? d * d : 0.;
        }
      for(int a = -2; a <= 2; ++a)
      {
        const double gap_a = slab_gap[0][a + 2];
        if(gap_a > best_distance)
          continue;
        for(int b = -2; b <= 2; ++b)
        {
          const double gap_ab = gap_a + slab_gap[1][b + 2];
          if(gap_ab > best_distance)
            continue;
          for(int c = -2; c <= 2; ++c)
          {
            if((a == 0 && b == 0 && c == 0) || gap_ab + slab_gap[2][c + 2] > best_distance)
              continue;
            const std::uint32_t found = chosen.find({v[0] + a, v[1] + b, v[2] + c});
            if(found == internal::Voxel_table::EMPTY)
              continue;
            const double d = squared_distance(copy[found]);
            if(d < best_distance || (d == best_distance && found < best))
            {
              best = found;
              best_distance = d;
            }
          }
        }
      }
      result.nearest_representative[i] = position[best];
    });
  return result;
}

} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_THIN_ON_VOXEL_GRID_H
