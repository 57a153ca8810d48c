// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The table of classify's feature groups and their computations, compiled once for every command
// that computes features (one instantiation of the package's feature templates).

#include "feature_groups.h"

#include "cgal_features.h"
#include "for_each_item.h"
#include "../command_line.h"
#include "../optimal_command.h"

#include <CGAL/Sigmoid_neighborhoods/compute_height_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_k_nearest_neighbors.h>
#include <CGAL/Sigmoid_neighborhoods/compute_point_features.h>
#include <CGAL/Sigmoid_neighborhoods/compute_pyramid_features.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>
#include <CGAL/Sigmoid_neighborhoods/Classification/add_point_features.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sigmoid_tool {

// What a group's computation reads: the point set, the neighbor rows that the package's groups share,
// and the pyramid that the two pyramid groups share (built by the first of them).
struct Feature_group_input
{
  const SN::Oriented_point_set& model;
  const Feature_options& options;
  const std::vector<std::uint32_t>& neighbor_indices;
  const std::vector<std::size_t>& neighbor_offsets;
  std::vector<SN::Pyramid_level> pyramid;
};

namespace {

namespace SNP = SN::parameters;

// The names the table and the groups that read each other share.
const char* const PYRAMID = "pyramid";
const char* const PYRAMID_SIGMOID = "pyramid-sigmoid";

bool has_group(const Feature_options& o, const char* group)
{
  return std::find(o.groups.begin(), o.groups.end(), group) != o.groups.end();
}

// The columns of the features `which` of the records `record(i)` of the points i < n, named with
// `suffix`; allocated first, then filled on `threads` threads (a value depends on its point alone).
template <typename Record>
void append_point_features(std::size_t n, const Record& record, const std::vector<SN::Point_feature>& which,
                           const std::string& suffix, unsigned int threads, std::vector<Feature_column>& columns)
{
  const std::size_t first = columns.size();
  for(SN::Point_feature f : which)
    columns.push_back({SN::point_feature_name(f) + suffix, {}});
  const std::ptrdiff_t count = std::ptrdiff_t(n);
  // the columns' first touch (a zero fill) a column per thread
  for_each_item(first, columns.size(), threads, [&](std::size_t c) { columns[c].values.resize(n); });
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(threads == 0 ? omp_get_max_threads() : int(threads))
#endif
  for(std::ptrdiff_t i = 0; i < count; ++i)
  {
    const SN::Point_features& p = record(std::size_t(i));
    for(std::size_t k = 0; k < which.size(); ++k)
      columns[first + k].values[std::size_t(i)] = p.value(which[k]);
  }
  (void)threads;
}

void append_point_features(const std::vector<SN::Point_features>& features,
                                  const std::vector<SN::Point_feature>& which, const std::string& suffix,
                                  unsigned int threads, std::vector<Feature_column>& columns)
{
  append_point_features(features.size(), [&](std::size_t i) -> const SN::Point_features& { return features[i]; },
                        which, suffix, threads, columns);
}

void append_height_features(const SN::Oriented_point_set& model, double cell, const std::string& suffix,
                                   std::vector<Feature_column>& columns)
{
  std::vector<SN::Height_features> heights;
  heights.reserve(model.points.size());
  SN::compute_height_features(model.points, cell, std::back_inserter(heights));
  Feature_column above{"height_above_lowest" + suffix, {}}, below{"height_below_highest" + suffix, {}},
    range_column{"vertical_range" + suffix, {}};
  above.values.reserve(heights.size());
  below.values.reserve(heights.size());
  range_column.values.reserve(heights.size());
  for(const SN::Height_features& h : heights)
  {
    above.values.push_back(h.height_above_lowest);
    below.values.push_back(h.height_below_highest);
    range_column.values.push_back(h.vertical_range);
  }
  columns.push_back(std::move(above));
  columns.push_back(std::move(below));
  columns.push_back(std::move(range_column));
}

// The suffix of a pyramid level's columns: its cell size, e.g. "_pyr0.5".
std::string pyramid_suffix(double cell) { return "_pyr" + number17(cell); }

// The pyramid of the groups pyramid and pyramid-sigmoid on `model`.
std::vector<SN::Pyramid_level> build_model_pyramid(const SN::Oriented_point_set& model, const Feature_options& o)
{
  return SN::build_point_pyramid<SN::Parallel_if_available_tag>(
    point_indices(model.points.size()), o.pyramid_cell_sizes(), o.pyramid_k,
    SNP::neighbor_search(CLASSIFICATION_NEIGHBOR_SEARCH, SNP::number_of_threads(o.threads, model_maps(model))));
}

// How wide a tile's halo must be for the pyramid's records of the tile's points `first` ... `last - 1`
// (of extent `extent` in x and y) to be the union's, checked on `model`, the tile and a halo of the
// union's points within `width` of the extent (read_tile_with_halo()): the result is at most `width`
// when they are. A point's records are its nearest representative's and those of that one's k
// neighbors among the representatives (and, where normals are estimated, the normals of these). Every
// point of the union within xy-distance W + inside(x) of x is read, inside(x) the distance of x to the
// extent's nearest side (negative outside). A representative read is the union's when its cell is
// whole, i.e. every union point of its cell is read; a cell meeting the ball of radius d around x lies
// within d + sqrt(2) c of x in xy. So for a point p, its nearest representative r at d and r's k-th
// neighbor at d_k: when every cell meeting the ball of radius d around p and of radius d_k around r
// is whole, the representatives in both balls are the union's (and no union representative in them
// is missing), so r and its row are the union's (ties break on the global order, which the read set
// keeps). A normal estimated on n neighbors is the union's when the ball of its n-th neighbor is read.
double pyramid_halo_width(const SN::Oriented_point_set& model, const Feature_options& o,
                                 const CGAL::Bbox_2& extent, std::size_t first, std::size_t last)
{
  const std::vector<SN::Pyramid_level> levels = build_model_pyramid(model, o);
  const bool sigmoid = has_group(o, PYRAMID_SIGMOID);
  const unsigned int normal_neighbors = model.normals_estimated ? model.estimation_neighbors : 0;
  auto distance = [&](std::size_t i, std::size_t j) { return std::sqrt(CGAL::squared_distance(model.points[i], model.points[j])); };
  // the halo point i needs to see every union point within `reach` of it
  auto needed = [&](std::size_t i, double reach) {
    return halo_needed(model.points[i].x(), model.points[i].y(), extent, reach);
  };
  auto normal_reach = [&](std::size_t i) {
    if(normal_neighbors == 0)
      return 0.;
    const std::size_t row = model.neighbor_offsets[i + 1] - model.neighbor_offsets[i];
    if(row < normal_neighbors)
      return std::numeric_limits<double>::infinity();
    return distance(i, model.neighbor_indices[model.neighbor_offsets[i] + normal_neighbors - 1]);
  };
  double width = 0.;
  for(const SN::Pyramid_level& level : levels)
  {
    const double cell = std::sqrt(2.) * level.thinning.cell_size;
    const auto& representatives = level.thinning.representatives;
    std::vector<char> seen(representatives.size(), 0);
    for(std::size_t i = first; i < last; ++i)
    {
      const std::uint32_t r = level.thinning.nearest_representative[i];
      width = std::max(width, needed(i, distance(i, representatives[r]) + cell));
      if(seen[r])
        continue;
      seen[r] = 1;
      const std::size_t begin = level.neighbor_offsets[r], end = level.neighbor_offsets[r + 1];
      const double d_k = distance(representatives[r], representatives[level.neighbor_indices[end - 1]]);
      width = std::max(width, needed(representatives[r], std::max(d_k + cell, normal_reach(representatives[r]))));
      if(sigmoid) // the weights read the neighbors' normals
        for(std::size_t e = begin; e < end; ++e)
          width = std::max(width, needed(representatives[level.neighbor_indices[e]],
                                         normal_reach(representatives[level.neighbor_indices[e]])));
    }
  }
  return width;
}

// The named parameters of the shared neighbor rows.
auto neighbor_rows(const Feature_group_input& in)
{
  return SNP::number_of_threads(
    in.options.threads, SNP::neighbor_indices(std::cref(in.neighbor_indices),
                                              SNP::neighbor_offsets(std::cref(in.neighbor_offsets), model_maps(in.model))));
}

const std::vector<SN::Point_feature>& shape_features()
{
  static const std::vector<SN::Point_feature> shape = SN::Classification::default_point_features();
  return shape;
}

// CGAL's generator: scales from each file's spacing (`voxel` 0), or in metres, anchored at the origin
// in the models that say so.
void compute_cgal(Feature_group_input& in, double voxel, bool grid_only, std::vector<Feature_column>& columns)
{
  const Feature_options& o = in.options;
  if(voxel > 0. && o.cgal_grids_at_origin)
    append_anchored_cgal_features(in.model, o.cgal_scales, voxel, o.threads, columns, grid_only);
  else
    append_cgal_features(in.model, o.cgal_scales, voxel, o.threads, columns, grid_only);
}

// The eigen features at the neighbor counts `sizes`, with the sigmoid weights or equal ones.
void compute_scales(Feature_group_input& in, const std::vector<unsigned int>& sizes, bool sigmoid,
                    std::vector<Feature_column>& columns)
{
  const Feature_options& o = in.options;
  const SN::Cosine_sigmoid weights = sigmoid ? SN::Cosine_sigmoid(o.sigmoid_a, o.sigmoid_b)
                                             : SN::Cosine_sigmoid(CGAL_PI, CGAL_PI);
  std::vector<std::vector<SN::Point_features>> per_point;
  per_point.reserve(in.model.points.size());
  SN::compute_point_features<SN::Parallel_if_available_tag>(point_indices(in.model.points.size()), weights, sizes,
                                                            std::back_inserter(per_point), neighbor_rows(in));
  for(std::size_t s = 0; s < sizes.size(); ++s)
    append_point_features(
      per_point.size(), [&](std::size_t i) -> const SN::Point_features& { return per_point[i][s]; }, shape_features(),
      (sigmoid ? "_sigmoid_k" : "_k") + std::to_string(sizes[s]), o.threads, columns);
}

// The eigen features at each point's optimal neighborhood: equal weights and the k of `criterion`
// (`triple` false), or the optimal sigmoid triple; the columns end in `suffix`.
void compute_optimal(Feature_group_input& in, SN::Neighborhood_criterion criterion, bool triple,
                     const std::string& suffix, std::vector<Feature_column>& columns)
{
  const Feature_options& o = in.options;
  std::vector<SN::Point_feature> which = shape_features();
  which.push_back(SN::Point_feature::NEIGHBORHOOD_SIZE);
  if(triple)
    for(SN::Point_feature f : {SN::Point_feature::SIGMOID_A, SN::Point_feature::SIGMOID_B, SN::Point_feature::RADIUS,
                               SN::Point_feature::DIMENSIONALITY_ERROR})
      which.push_back(f);
  const std::vector<double> grid = triple ? SN::defaults::angle_grid() : std::vector<double>{CGAL_PI};
  std::vector<SN::Point_features> features;
  features.reserve(in.model.points.size());
  SN::compute_optimal_point_features<SN::Parallel_if_available_tag>(
    point_indices(in.model.points.size()), std::back_inserter(features),
    SNP::criterion(criterion,
                   SNP::k_min(o.k_min, SNP::k_max(o.k_max, SNP::a_grid(grid, SNP::b_grid(grid, neighbor_rows(in)))))));
  append_point_features(features, which, suffix, o.threads, columns);
}

// A pyramid group: its levels with the sigmoid weights (`sigmoid`: those of --pyramid-sigmoid-cells)
// or equal ones, and the heights in the levels' cells; the levels and heights that the group pyramid
// gives are given once when both groups are there.
void compute_pyramid(Feature_group_input& in, bool sigmoid, std::vector<Feature_column>& columns)
{
  const Feature_options& o = in.options;
  const SN::Oriented_point_set& model = in.model;
  const bool both = sigmoid && has_group(o, PYRAMID);
  if(in.pyramid.empty())
    in.pyramid = build_model_pyramid(model, o);
  const std::vector<double> cells = o.pyramid_cell_sizes();
  // this group's levels: with the sigmoid weights, or equal ones where the group pyramid does not give them
  std::vector<std::size_t> weighted, equal;
  for(std::size_t l = 0; l < cells.size(); ++l)
    if(sigmoid && o.pyramid_sigmoid_level(cells[l]))
      weighted.push_back(l);
    else if(!both)
      equal.push_back(l);
  // the weighted levels, then the equal ones: the columns in that order, each point's record its
  // nearest representative's on the level, read in parallel
  for(const bool with_weights : {true, false})
  {
    const std::vector<std::size_t>& which = with_weights ? weighted : equal;
    if(which.empty())
      continue;
    // the group's levels lent from the shared pyramid and given back: a copy costs a pass per level
    std::vector<SN::Pyramid_level> levels;
    for(std::size_t l : which)
      levels.push_back(std::move(in.pyramid[l]));
    const SN::Cosine_sigmoid weights = with_weights ? SN::Cosine_sigmoid(o.sigmoid_a, o.sigmoid_b)
                                                    : SN::Cosine_sigmoid(CGAL_PI, CGAL_PI);
    std::vector<std::vector<SN::Point_features>> records;
    std::exception_ptr failure;
    try
    {
      records = SN::compute_pyramid_level_features<SN::Parallel_if_available_tag>(
        point_indices(model.points.size()), levels, o.pyramid_k, weights,
        SNP::neighbor_search(CLASSIFICATION_NEIGHBOR_SEARCH, SNP::number_of_threads(o.threads, model_maps(model))));
    }
    catch(...)
    {
      failure = std::current_exception();
    }
    for(std::size_t c = 0; c < which.size(); ++c)
      in.pyramid[which[c]] = std::move(levels[c]);
    if(failure)
      std::rethrow_exception(failure);
    for(std::size_t c = 0; c < which.size(); ++c)
    {
      const std::vector<std::uint32_t>& nearest = in.pyramid[which[c]].thinning.nearest_representative;
      append_point_features(
        model.points.size(), [&](std::size_t i) -> const SN::Point_features& { return records[c][nearest[i]]; },
        shape_features(), (with_weights ? "_sigmoid" : "") + pyramid_suffix(cells[which[c]]), o.threads, columns);
    }
  }
  if(!both)
  {
    // the heights of the cell sizes side by side: each one pass over the points into a map of cells
    std::vector<std::vector<Feature_column>> heights(cells.size());
    for_each_item(0, cells.size(), o.threads,
                  [&](std::size_t c) { append_height_features(model, cells[c], pyramid_suffix(cells[c]), heights[c]); });
    for(std::vector<Feature_column>& h : heights)
      for(Feature_column& column : h)
        columns.push_back(std::move(column));
  }
}

// The halo of the heights in cells of side `largest`: a cell meeting the tile lies within its side
// of the tile. The relative margin covers the rounding of x / side at the cells' borders while
// |x| / side stays below 10^9.
double cells_halo(double largest) { return largest * (1. + 1e-6); }

// The pyramid's: the heights in its cells, and as a first guess 4 coarsest cells (a point's nearest
// representative within a cell's diagonal, 1.7 cells, the k = 10 nearest of that one within about 2
// cells on a surface, and their cells; the six IGN tiles need 3.4 to 3.9); pyramid_halo_width()
// checks it on what was read, and the tile is read again with a wider halo when it does not hold.
double pyramid_halo(const Feature_options& o, bool first_guess)
{
  const double top = o.pyramid_cell_sizes().back();
  return first_guess ? std::max(cells_halo(top), 4. * top) : cells_halo(top);
}

// cgal-metric's and cgal-grid's anchored grids: their windows, with the cells' margin; their
// neighbors are checked on what was read (anchored_cgal_halo_width()).
double anchored_cgal_halo(const Feature_options& o, bool) { return o.cgal_grids_at_origin ? cells_halo(anchored_cgal_grid_reach(o)) : 0.; }

double anchored_cgal_checked_halo(const SN::Oriented_point_set& model, const Feature_options& o,
                                  const CGAL::Bbox_2& extent, std::size_t first, std::size_t last, bool grid_only)
{
  return o.cgal_grids_at_origin ? anchored_cgal_halo_width(model, o.cgal_scales, o.cgal_voxel, grid_only, o.threads,
                                                           extent, first, last)
                                : 0.;
}

unsigned int no_neighbors(const Feature_options&) { return 0; }
unsigned int optimal_neighbors(const Feature_options& o) { return o.k_max; }
unsigned int scale_neighbors(const Feature_options& o) { return *std::max_element(o.scales.begin(), o.scales.end()); }
double no_halo(const Feature_options&, bool) { return 0.; }
bool any_tile(const Feature_options&) { return true; }
bool anchored_at_origin(const Feature_options& o) { return o.cgal_grids_at_origin; }

const char* const CGAL_FAMILY = "CGAL's features";

} // namespace

const std::vector<Feature_group>& feature_groups()
{
  typedef std::vector<Feature_column> Columns;
  static const std::vector<Feature_group> groups{
    {"cgal",
     "CGAL's Point_set_feature_generator on 5 scales (eigenvalues, heights, ...), the\n"
     "first from each file's spacing, as CGAL chooses it",
     no_neighbors, no_halo, nullptr,
     [](const Feature_options&) { return false; }, // CGAL takes its scales from the whole set's spacing
     [](Feature_group_input& in, Columns& c) { compute_cgal(in, 0., false, c); }, CGAL_FAMILY, false},
    {"cgal-metric",
     "the same on scales in metres: --cgal-voxel 0.5 m times 1, 2, 4 ... (a model\n"
     "applies at another density), its grids anchored at the origin (tile by tile)",
     no_neighbors, anchored_cgal_halo,
     [](const SN::Oriented_point_set& m, const Feature_options& o, const CGAL::Bbox_2& e, std::size_t f, std::size_t l) {
       return anchored_cgal_checked_halo(m, o, e, f, l, false);
     },
     anchored_at_origin, [](Feature_group_input& in, Columns& c) { compute_cgal(in, in.options.cgal_voxel, false, c); },
     CGAL_FAMILY, true},
    {"cgal-grid",
     "the features of cgal-metric's planimetric grids alone (vertical dispersion,\n"
     "elevation, heights below and above, vertical range): no eigen analysis",
     no_neighbors, anchored_cgal_halo,
     [](const SN::Oriented_point_set& m, const Feature_options& o, const CGAL::Bbox_2& e, std::size_t f, std::size_t l) {
       return anchored_cgal_checked_halo(m, o, e, f, l, true);
     },
     anchored_at_origin, [](Feature_group_input& in, Columns& c) { compute_cgal(in, in.options.cgal_voxel, true, c); },
     CGAL_FAMILY, true},
    {"k20", "the eigen features (linearity ... normal_z) at k = 20, equal weights",
     [](const Feature_options& o) { return o.fixed_k; }, no_halo, nullptr, any_tile,
     [](Feature_group_input& in, Columns& c) { compute_scales(in, {in.options.fixed_k}, false, c); }, nullptr, false},
    {"eigenentropy", "the same at the eigenentropy-optimal k of Weinmann et al., equal weights, and k",
     optimal_neighbors, no_halo, nullptr, any_tile,
     [](Feature_group_input& in, Columns& c) {
       compute_optimal(in, SN::Neighborhood_criterion::EIGENENTROPY, false, "_eigenentropy", c);
     },
     nullptr, false},
    {"dimensionality", "the same at the E_dim-optimal k, equal weights, and k", optimal_neighbors, no_halo, nullptr,
     any_tile,
     [](Feature_group_input& in, Columns& c) {
       compute_optimal(in, SN::Neighborhood_criterion::DIMENSIONALITY, false, "_dimensionality", c);
     },
     nullptr, false},
    {"optimal", "the same at the optimal sigmoid triple (a*, b*, k*), and k, a, b, the radius", optimal_neighbors,
     no_halo, nullptr, any_tile,
     [](Feature_group_input& in, Columns& c) {
       compute_optimal(in, SN::Neighborhood_criterion::DIMENSIONALITY, true, "_optimal", c);
     },
     nullptr, false},
    {"multiscale", "the eigen features at k = 10, 25, 50, 100 (--scales), equal weights", scale_neighbors, no_halo,
     nullptr, any_tile, [](Feature_group_input& in, Columns& c) { compute_scales(in, in.options.scales, false, c); },
     nullptr, false},
    {"multiscale-sigmoid",
     "the same with the sigmoid weights of --sigmoid A,B (default 30deg,60deg; the\n"
     "smaller angle is a, the larger b, one angle a step; pyramid-sigmoid's weights too)",
     scale_neighbors, no_halo, nullptr, any_tile,
     [](Feature_group_input& in, Columns& c) { compute_scales(in, in.options.scales, true, c); }, nullptr, false},
    {"height", "z above the lowest point, below the highest and the range in 2.5, 5, 10 m cells", no_neighbors,
     [](const Feature_options& o, bool) { return cells_halo(*std::max_element(o.cell_sizes.begin(), o.cell_sizes.end())); },
     nullptr, any_tile,
     [](Feature_group_input& in, Columns& c) {
       for(double cell : in.options.cell_sizes)
         append_height_features(in.model, cell, "_cell" + number17(cell), c);
     },
     nullptr, false},
    {PYRAMID,
     "the eigen features at k = 10 on voxel grids of --pyramid-cell x 2^l metres, l below\n"
     "--pyramid-levels, each point's from its nearest representative, and the heights\n"
     "in the same cells (scales in metres: a model applies at another density)",
     no_neighbors, pyramid_halo, pyramid_halo_width, any_tile,
     [](Feature_group_input& in, Columns& c) { compute_pyramid(in, false, c); }, nullptr, true},
    {PYRAMID_SIGMOID,
     "the same with the sigmoid weights of --sigmoid, on the levels of\n"
     "--pyramid-sigmoid-cells C,... (default every level; the others with equal weights)",
     no_neighbors, pyramid_halo, pyramid_halo_width, any_tile,
     [](Feature_group_input& in, Columns& c) { compute_pyramid(in, true, c); }, nullptr, true}};
  return groups;
}

std::vector<Feature_column> compute_feature_columns(const SN::Oriented_point_set& model, const Feature_options& o,
                                                    const std::function<void(const std::string&)>& progress)
{
  const unsigned int k_needed = largest_neighborhood(o);
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> offsets;
  const bool model_rows = k_needed > 0 && !model.neighbor_offsets.empty() &&
                          model.neighbor_indices.size() >= std::size_t(k_needed) * model.points.size();
  if(k_needed > 0 && !model_rows)
  {
    if(model.points.size() < std::size_t(k_needed) + 1)
      throw SN::Input_error("needs at least " + std::to_string(k_needed + 1) + " distinct points for the features, got " +
                            std::to_string(model.points.size()));
    progress("neighbors");
    SN::compute_k_nearest_neighbors<SN::Parallel_if_available_tag>(
      point_indices(model.points.size()), k_needed, indices, offsets, SNP::neighbor_search(CLASSIFICATION_NEIGHBOR_SEARCH, SNP::number_of_threads(o.threads, model_maps(model))));
  }
  Feature_group_input in{model, o, model_rows ? model.neighbor_indices : indices,
                         model_rows ? model.neighbor_offsets : offsets, {}};
  std::vector<Feature_column> columns;
  for(const Feature_group* g : groups_of(o))
  {
    progress(g->name);
    g->compute(in, columns);
  }
  return columns;
}

double checked_halo_width_of_tile(const SN::Oriented_point_set& model, const Feature_options& o,
                                  const CGAL::Bbox_2& extent, std::size_t first, std::size_t last)
{
  double width = 0.;
  if(first == last)
    return width;
  std::vector<decltype(Feature_group::checked_halo)> done; // the pyramid groups share theirs
  for(const Feature_group* g : groups_of(o))
    if(g->checked_halo != nullptr && std::find(done.begin(), done.end(), g->checked_halo) == done.end())
    {
      done.push_back(g->checked_halo);
      width = std::max(width, g->checked_halo(model, o, extent, first, last));
    }
  return width;
}

} // namespace sigmoid_tool
