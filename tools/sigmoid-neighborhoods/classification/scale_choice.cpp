// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// classify train's choice of the first scale in metres (scale_choice.h).

#include "scale_choice.h"

#include "classify_common.h"
#include "confusion.h"
#include "feature_groups.h"
#include "training_rows.h"

#include <CGAL/Sigmoid_neighborhoods/Classification/Ethz_forest.h>
#include <Sigmoid_neighborhoods_readers/estimate_oriented_normals.h>
#include <CGAL/Sigmoid_neighborhoods/concurrency.h>

#include <CGAL/Real_timer.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {
namespace classification {

// The held-out points predicted per fold, at most: their rows are the choice's largest memory.
constexpr std::size_t TEST_POINTS_PER_FOLD = 40000;

const std::vector<double>& scale_ladder()
{
  static const std::vector<double> ladder{0.0625, 0.125, 0.25, 0.5, 1.};
  return ladder;
}

bool has_metric_scales(const Feature_options& o)
{
  for(const Feature_group* g : groups_of(o))
    if(g->metric_scales)
      return true;
  return false;
}

Feature_options with_first_scale(Feature_options o, double first)
{
  const double factor = first / o.pyramid_cell;
  for(double& c : o.pyramid_sigmoid_cells)
    c *= factor; // the ladder's steps are powers of two: exact
  o.cgal_voxel = first;
  o.pyramid_cell = first;
  return o;
}

namespace {

// What the choice knows of a file before its features, from its labels and positions alone: each
// point's class and fold.
struct Fold_labels
{
  std::vector<int> truth;
  std::vector<unsigned char> fold;
};

// A file of the choice once featured: its points with their normals, the points that a forest
// trains on or predicts (`selected`), and the columns of the groups without scales in metres at
// these points alone, computed once for every candidate scale (their neighbor rows, up to 100 a
// point, are then freed).
struct Fold_file
{
  Featured_file file;
  std::vector<std::size_t> selected;
  std::map<std::string, std::vector<Feature_column>> fixed_groups; // at the selected points
};

// `columns` at the points `selected` alone.
std::vector<Feature_column> at_points(std::vector<Feature_column> columns, const std::vector<std::size_t>& selected)
{
  for(Feature_column& c : columns)
  {
    std::vector<double> values(selected.size());
    for(std::size_t i = 0; i < selected.size(); ++i)
      values[i] = c.values[selected[i]];
    c.values = std::move(values);
  }
  return columns;
}

// The columns of the groups of `o` on `f` at its selected points, in the order the groups give
// them (a column that an earlier group gave kept once, as compute_feature_columns() gives the set):
// those with scales in metres computed here, the others as computed before.
std::vector<Feature_column> selected_columns(const Fold_file& f, const Feature_options& o, double first)
{
  std::vector<Feature_column> columns;
  std::set<std::string> names;
  for(const Feature_group* g : groups_of(o))
  {
    std::vector<Feature_column> group;
    if(g->metric_scales)
    {
      Feature_options one = o;
      one.groups = {g->name};
      group = at_points(compute_feature_columns(f.file.model, one, [&](const std::string& step) {
                          progress(f.file.path + ": scale " + number17(first) + " m: " + step);
                        }),
                        f.selected);
    }
    else
      group = f.fixed_groups.at(g->name);
    for(Feature_column& c : group)
      if(names.insert(c.name).second)
        columns.push_back(std::move(c));
  }
  return columns;
}

// The fold of a point: the parity of its block in a checkerboard of 4 x 4 blocks over `extent`.
unsigned char fold_of(const SN::Oriented_point_set::Point_3& p, const CGAL::Bbox_2& extent)
{
  auto block = [](double v, double lo, double hi) {
    const double width = (hi - lo) / 4.;
    const int b = width > 0. ? int(std::floor((v - lo) / width)) : 0;
    return std::clamp(b, 0, 3);
  };
  return static_cast<unsigned char>((block(p.x(), extent.xmin(), extent.xmax()) +
                                     block(p.y(), extent.ymin(), extent.ymax())) & 1);
}

// The points of a file of `n` points that its copy thinned 4x keeps: each with probability 1/4, a
// generator seeded by `seed`.
std::vector<std::size_t> thinned_points(std::size_t n, unsigned int seed)
{
  std::vector<std::size_t> kept;
  std::mt19937 random(seed);
  for(std::size_t i = 0; i < n; ++i)
    if((random() & 3u) == 0)
      kept.push_back(i);
  return kept;
}

// A copy of `f` at its points `kept`, their normals estimated again on them, as a survey 4x thinner
// would have them.
Featured_file thinned_copy(const Featured_file& f, const std::vector<std::size_t>& kept, const Label_mapping& labels,
                           const SN::Normal_options& normals, const Feature_options& features)
{
  Featured_file t;
  t.path = f.path + " (thinned 4x)";
  const SN::Oriented_point_set& m = f.model;
  for(std::size_t i : kept)
  {
    t.model.points.push_back(m.points[i]);
    t.model.labels.push_back(m.labels[i]);
  }
  SN::Normal_options o = normals;
  o.kept_neighbors = largest_neighborhood(features);
  o.neighbors = std::min<unsigned int>(o.neighbors, unsigned(std::max<std::size_t>(t.model.points.size(), 1) - 1));
  read_input(t.path, [&] {
    SN::estimate_oriented_normals(t.model, o);
    return 0;
  });
  add_features(t, labels, true, features, false);
  return t;
}

// The truth of the points of fold `fold` that train its forest: at most `cap` per class over the
// files, evenly spaced; -1 elsewhere.
std::vector<std::vector<int>> training_truth(const std::vector<Fold_labels>& files, unsigned char fold,
                                             std::size_t classes, std::size_t cap)
{
  std::vector<int> all;
  for(const Fold_labels& f : files)
    for(std::size_t i = 0; i < f.truth.size(); ++i)
      all.push_back(f.fold[i] == fold ? f.truth[i] : -1);
  cap_points_per_class(all, classes, cap);
  std::vector<std::vector<int>> truth;
  std::size_t at = 0;
  for(const Fold_labels& f : files)
  {
    truth.emplace_back(all.begin() + std::ptrdiff_t(at), all.begin() + std::ptrdiff_t(at + f.truth.size()));
    at += f.truth.size();
  }
  return truth;
}

// The labeled points of `truth` (one vector per file) thinned to at most `limit` evenly spaced over
// the files, whatever their class: the classes' proportions, which the IoU depends on, stay.
void keep_evenly(std::vector<std::vector<int>>& truth, std::size_t limit)
{
  std::size_t labeled = 0;
  for(const std::vector<int>& t : truth)
    labeled += std::size_t(std::count_if(t.begin(), t.end(), [](int c) { return c >= 0; }));
  if(labeled <= limit)
    return;
  std::size_t seen = 0, kept = 0;
  for(std::vector<int>& t : truth)
    for(int& c : t)
    {
      if(c < 0)
        continue;
      const std::size_t wanted = (++seen) * limit / labeled; // as cap_points_per_class(), over all classes
      if(wanted > kept)
        ++kept;
      else
        c = -1;
    }
}

// The pooled confusion of the two folds' forests, each trained on `train[fold]` and predicting the
// other fold's `test`.
Confusion cross_validated(const std::array<Training_rows, 2>& train, const std::array<Training_rows, 2>& test,
                          std::size_t width, const Classifier_settings& s)
{
  Confusion pooled(s.labels.names.size());
  for(std::size_t fold = 0; fold < 2; ++fold)
  {
    const SN::Classification::Ethz_forest forest = SN::Classification::Ethz_forest::train<SN::Parallel_if_available_tag>(
      train[fold].values, train[fold].labels, s.labels.names.size(), s.trees, s.depth,
      SN::parameters::number_of_threads(s.features.threads));
    const Training_rows& other = test[1 - fold];
    std::vector<int> predicted;
    std::vector<std::vector<float>> confidence;
    forest.classify<SN::Parallel_if_available_tag>(
      other.labels.size(), [&](std::size_t i, std::size_t f) { return other.values[1 + i * width + f]; }, predicted,
      confidence, SN::parameters::number_of_threads(s.features.threads));
    for(std::size_t i = 0; i < predicted.size(); ++i)
      pooled.add(other.labels[i], predicted[i]);
  }
  return pooled;
}

// Per file, the truth at the points a forest reads, per fold of the checkerboard.
typedef std::array<std::vector<std::vector<int>>, 2> Truth;

// The training and the test points of each fold: of the files (`train`, `test`) and of their copies
// thinned 4x (`thinned`), whose points are `kept` of each file.
struct Fold_truths
{
  Truth train, thinned, test;
  std::vector<std::vector<std::size_t>> kept;
};

// First the files' labels and positions alone (no normals, no neighbor rows): they give the folds
// and the points that the forests read, so that each file is then featured on its own and keeps
// its columns at those points alone. (Reading every file with its rows first held them all at
// once: 5.8 GB for 10 M points.)
Fold_truths read_fold_truths(const std::vector<std::string>& paths, const Classifier_settings& s, std::size_t cap)
{
  const std::size_t classes = s.labels.names.size();
  std::vector<Fold_labels> labeled(paths.size()), thinned_labeled(paths.size());
  Fold_truths truths;
  truths.kept.resize(paths.size());
  {
    std::vector<std::vector<SN::Oriented_point_set::Point_3>> points;
    CGAL::Bbox_2 extent;
    for(std::size_t i = 0; i < paths.size(); ++i)
    {
      Featured_file f = read_labels(paths[i], s);
      for(const auto& p : f.model.points)
        extent += CGAL::Bbox_2(p.x(), p.y(), p.x(), p.y());
      labeled[i].truth = std::move(f.truth);
      points.push_back(std::move(f.model.points));
    }
    for(std::size_t i = 0; i < paths.size(); ++i)
    {
      for(const auto& p : points[i])
        labeled[i].fold.push_back(fold_of(p, extent));
      std::vector<SN::Oriented_point_set::Point_3>().swap(points[i]);
      truths.kept[i] = thinned_points(labeled[i].truth.size(), unsigned(i) + 1);
      for(std::size_t p : truths.kept[i])
      {
        thinned_labeled[i].truth.push_back(labeled[i].truth[p]);
        thinned_labeled[i].fold.push_back(labeled[i].fold[p]);
      }
    }
  }
  for(unsigned char fold = 0; fold < 2; ++fold)
  {
    truths.train[fold] = training_truth(labeled, fold, classes, cap);
    truths.thinned[fold] = training_truth(thinned_labeled, fold, classes, cap);
    truths.test[fold] = training_truth(labeled, fold, classes, 0);
    keep_evenly(truths.test[fold], TEST_POINTS_PER_FOLD);
  }
  return truths;
}

// The points of file `i` that a forest reads (`f.selected`), their truth at those points alone, and
// the groups of `fixed` (those no candidate changes) computed there once; then the neighbor rows,
// which only those groups read, are freed: the choice holds the selected points' columns, not every
// point's rows.
void select_points(Fold_file& f, std::size_t i, const std::vector<Truth*>& truths, const Feature_options& fixed)
{
  for(std::size_t p = 0; p < f.file.truth.size(); ++p)
    if(std::any_of(truths.begin(), truths.end(), [&](const Truth* t) {
         return (*t)[0][i][p] >= 0 || (*t)[1][i][p] >= 0;
       }))
      f.selected.push_back(p);
  for(Truth* t : truths)
    for(std::vector<std::vector<int>>& fold : *t)
    {
      std::vector<int> at_selected(f.selected.size());
      for(std::size_t j = 0; j < f.selected.size(); ++j)
        at_selected[j] = fold[i][f.selected[j]];
      fold[i] = std::move(at_selected);
    }
  for(const Feature_group* g : groups_of(fixed))
  {
    Feature_options one = fixed;
    one.groups = {g->name};
    f.fixed_groups[g->name] = at_points(compute_feature_columns(f.file.model, one, [&](const std::string& step) {
                                          progress(f.file.path + ": " + step);
                                        }),
                                        f.selected);
  }
  std::vector<std::uint32_t>().swap(f.file.model.neighbor_indices);
  std::vector<std::size_t>().swap(f.file.model.neighbor_offsets);
}

// Each file featured, and its copy thinned 4x, at their selected points (select_points()).
void read_fold_files(const std::vector<std::string>& paths, const Classifier_settings& s, Fold_truths& truths,
                     std::vector<Fold_file>& files, std::vector<Fold_file>& thinned)
{
  Feature_options fixed = s.features;
  fixed.groups.clear();
  for(const Feature_group* g : groups_of(s.features))
    if(!g->metric_scales)
      fixed.groups.push_back(g->name);
  for(std::size_t i = 0; i < paths.size(); ++i)
  {
    Fold_file f, t;
    f.file = read_and_feature(paths[i], s.labels, true, s.normals, s.features, false);
    check_same_points(f.file, truths.train[0][i].size());
    progress(paths[i] + ": thinned 4x for the choice of scales");
    t.file = thinned_copy(f.file, truths.kept[i], s.labels, s.normals, s.features);
    std::vector<std::size_t>().swap(truths.kept[i]);
    select_points(f, i, {&truths.train, &truths.test}, fixed);
    select_points(t, i, {&truths.thinned}, fixed);
    files.push_back(std::move(f));
    thinned.push_back(std::move(t));
  }
}

// The cross-validated mean IoU of the first scale `first`, at the files' density and trained on the
// thinned copies, added to `report`.
void score_first_scale(double first, const Classifier_settings& s, const std::vector<Fold_file>& files,
                       const std::vector<Fold_file>& thinned, const Fold_truths& truths, Scale_choice_report& report)
{
  const Feature_options o = with_first_scale(s.features, first);
  std::array<Training_rows, 2> train, test, thin;
  std::vector<std::string> names;
  // each file's features computed once, its rows appended to every set of rows that takes them
  auto append = [&](const std::vector<Fold_file>& set, const std::vector<std::pair<const Truth*, std::array<Training_rows, 2>*>>& targets) {
    for(std::size_t i = 0; i < set.size(); ++i)
    {
      const std::vector<Feature_column> columns = selected_columns(set[i], o, first);
      if(names.empty())
        names = column_names(columns);
      for(const auto& target : targets)
        for(std::size_t fold = 0; fold < 2; ++fold)
          append_training_rows(columns, (*target.first)[fold][i], names, o.threads, (*target.second)[fold]);
    }
  };
  append(files, {{&truths.train, &train}, {&truths.test, &test}});
  append(thinned, {{&truths.thinned, &thin}});
  for(std::size_t fold = 0; fold < 2; ++fold)
    if(train[fold].labels.empty() || thin[fold].labels.empty() || test[fold].labels.empty())
      throw Scale_choice_impossible("too few labeled points to choose the scales in metres (a fold of the "
                                    "checkerboard is empty): give --cgal-voxel and --pyramid-cell");
  report.same_density.push_back(cross_validated(train, test, names.size(), s).mean_iou());
  report.thinned.push_back(cross_validated(thin, test, names.size(), s).mean_iou());
  report.training_points = train[0].labels.size() + train[1].labels.size();
  report.test_points = test[0].labels.size() + test[1].labels.size();
}

// choose_first_scale() without its last step
Scale_choice_report choose(const std::vector<std::string>& paths, const Classifier_settings& s, std::size_t cap)
{
  CGAL::Real_timer timer;
  timer.start();
  Fold_truths truths = read_fold_truths(paths, s, cap);
  std::vector<Fold_file> files, thinned;
  read_fold_files(paths, s, truths, files, thinned);

  Scale_choice_report report;
  report.ladder = scale_ladder();
  report.cap = cap;
  for(double first : report.ladder)
    score_first_scale(first, s, files, thinned, truths, report);
  // the best of the worse of both densities; ties to the coarser scale
  double best = -std::numeric_limits<double>::infinity();
  for(std::size_t c = 0; c < report.ladder.size(); ++c)
  {
    const double score = std::min(report.same_density[c], report.thinned[c]);
    if(score >= best)
    {
      best = score;
      report.chosen = report.ladder[c];
    }
  }
  report.seconds = timer.time();
  return report;
}

} // namespace

Scale_choice_report choose_first_scale(const std::vector<std::string>& paths, const Classifier_settings& s,
                                       std::size_t cap)
{
  const Scale_choice_report report = choose(paths, s, cap);
  // The choice's many columns, freed, stay in glibc's heaps, between blocks still held; the training
  // that follows allocates its own, so without this they add to its peak (0.75 GB, +11 %, on 10 M
  // points).
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  return report;
}

} // namespace classification
} // namespace sigmoid_tool
