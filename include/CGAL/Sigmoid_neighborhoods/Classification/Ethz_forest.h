// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): Sigmoid_neighborhoods contributors

#ifndef CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ETHZ_FOREST_H
#define CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ETHZ_FOREST_H

#include <CGAL/Sigmoid_neighborhoods/Classification/Feature_values.h>
#include <CGAL/Sigmoid_neighborhoods/parameters.h>
#include <CGAL/Sigmoid_neighborhoods/internal/Search_settings.h>
#include <CGAL/Sigmoid_neighborhoods/internal/parallel.h>

#include <CGAL/Classification/ETHZ/internal/random-forest/forest.hpp>
#include <CGAL/Classification/ETHZ/internal/random-forest/node-gini.hpp>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Sigmoid_neighborhoods {
namespace Classification {

/*!
  \ingroup PkgSigmoidNeighborhoodsClassification
  the random forest of CGAL's `CGAL::Classification::ETHZ::Random_forest_classifier`, read from
  the bytes its `save_configuration()` writes, that classifies many items on the package's
  deterministic parallel loop.

  CGAL's classifier reads each value through a `Feature_set`, which copies a shared pointer per
  feature and item: on more than one thread all threads then write the same reference counts, and
  two threads ran slower than one. `classify()` gives the labels and confidences of CGAL's
  `classify()` with that classifier (the votes clamped to [0, 1], the first most confident label),
  bit for bit, for any number of threads.

  CGAL's reader checks nothing: truncated or forged bytes make it allocate without bound, recurse
  until the stack ends, or read a feature past the item's. The constructor checks the bytes against
  the format of CGAL 5.5's ETHZ forest first (its parameters, a tree count, each tree's nodes depth
  first: a leaf flag, two counts, the split's feature and threshold, one vote per label).
*/
class Ethz_forest
{
  // CGAL 5.5's axis-aligned split with a threshold from the start: a node whose split proposals all
  // failed keeps its default split, feature -1, whose threshold CGAL leaves uninitialised and then
  // compares its items to (the trees would depend on what the memory held). The same bytes on disk.
  struct Splitter : CGAL::internal::liblearning::RandomForest::AxisAlignedSplitter
  {
    Splitter() { threshold = 0.f; }
    // implicit: CGAL's node assigns each proposal of its split generator to its splitter
    Splitter(const AxisAlignedSplitter& proposal) : AxisAlignedSplitter(proposal) {}
  };
  typedef CGAL::internal::liblearning::RandomForest::RandomForest<
    CGAL::internal::liblearning::RandomForest::NodeGini<Splitter>>
    Forest;

public:
  /// what is wrong with `bytes` as a forest of `number_of_labels` labels reading `number_of_features`
  /// features; empty if nothing
  static std::string problem(const std::string& bytes, std::size_t number_of_labels, std::size_t number_of_features)
  {
    std::size_t at = 0;
    auto take_u32 = [&](std::uint32_t& v) {
      if(bytes.size() - at < 4)
        return false;
      std::memcpy(&v, bytes.data() + at, 4);
      at += 4;
      return true;
    };
    std::uint32_t params[7];
    for(std::uint32_t& v : params)
      if(!take_u32(v))
        return "it ends in its parameters";
    at += 4; // the sample reduction, a float
    std::uint32_t trees = 0;
    if(bytes.size() < at || !take_u32(trees))
      return "it ends in its parameters";
    if(params[0] != number_of_labels)
      return "it votes for " + std::to_string(params[0]) + " classes, the model names " +
             std::to_string(number_of_labels);
    if(params[1] != number_of_features)
      return "it reads " + std::to_string(params[1]) + " features, the model names " +
             std::to_string(number_of_features);
    if(trees == 0)
      return "it has no tree";
    const std::size_t node_bytes = 1 + 4 + 4 + 4 + 4 + 4 * std::size_t(number_of_labels);
    // deeper than any forest CGAL trains (its depth is a 32-bit count, but each level halves the samples)
    const std::size_t deepest = 1024;
    for(std::uint32_t t = 0; t < trees; ++t)
    {
      std::vector<std::size_t> pending{0}; // the depths of the nodes still to read
      while(!pending.empty())
      {
        const std::size_t depth = pending.back();
        pending.pop_back();
        if(bytes.size() - at < node_bytes)
          return "it ends in tree " + std::to_string(t + 1) + " of " + std::to_string(trees);
        if(depth > deepest)
          return "tree " + std::to_string(t + 1) + " is deeper than " + std::to_string(deepest) + " levels";
        const bool leaf = bytes[at] != 0;
        std::int32_t feature = 0;
        std::memcpy(&feature, bytes.data() + at + 9, 4);
        // -1: a split no proposal made, which reads the float before the item's (classify())
        if(!leaf && (feature < -1 || (feature >= 0 && std::size_t(feature) >= number_of_features)))
          return "tree " + std::to_string(t + 1) + " splits on feature " + std::to_string(feature) + " of " +
                 std::to_string(number_of_features);
        at += node_bytes;
        if(!leaf)
        {
          pending.push_back(depth + 1);
          pending.push_back(depth + 1);
        }
      }
    }
    if(at != bytes.size())
      return std::to_string(bytes.size() - at) + " bytes follow its last tree";
    return std::string();
  }

  /// the forest of `bytes` (as `save_configuration()` writes it) for `number_of_labels` labels and
  /// `number_of_features` features; throws `std::invalid_argument` with `problem()` if it is not one
  Ethz_forest(const std::string& bytes, std::size_t number_of_labels, std::size_t number_of_features)
    : m_labels(number_of_labels), m_features(number_of_features)
  {
    const std::string wrong = problem(bytes, number_of_labels, number_of_features);
    if(!wrong.empty())
      throw std::invalid_argument(wrong);
    CGAL::internal::liblearning::RandomForest::ForestParams params;
    m_forest = std::make_unique<Forest>(params);
    std::istringstream in(bytes);
    m_forest->read(in);
  }

  /*!
    trains the forest of CGAL's `Random_forest_classifier::train()` on `labels.size()` items: the same
    trees, bit for bit, as that classifier trained with `num_trees` and `max_depth` on a `Feature_set`
    of `Feature_values` holding these values, its ground truth listing these items' labels (and -1
    for the items it skips), for any number of threads. CGAL's classifier copies every value into a
    matrix of its own, grown by `push_back`, and trains its trees in parallel on TBB alone; here the
    caller's matrix is read in place and the trees are trained on the package's parallel loop, each
    from its own seed as CGAL seeds it.
    \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
    \tparam FeatureRange a contiguous range of `float` with `data()` and `size()` (`std::vector<float>`,
    with any allocator)
    \param features one float, then the rows: `features[1 + i * f + j]` the feature `j` of item `i`,
    `f` the number of features, as `Feature_values` stores them (`Feature_values::stored_value()`).
    The first float is read where CGAL 5.5 reads before the first row: a node whose split proposals
    all failed (its items equal in every feature it drew) keeps the feature -1, and its items are
    then sent left or right by the float before each row. Write 0 there, as `classify()` does before
    each item; CGAL's own matrix has no such float, and reads outside its memory.
    \param labels the label of each item, in [0, `number_of_labels`)
    \param number_of_labels the labels the forest votes for
    \param num_trees the number of trees (CGAL's default: 25)
    \param max_depth the depth of the trees at most (CGAL's default: 20)
    \param np optional: `number_of_threads` (0, the default: all)
    \pre `labels` is not empty, `features.size() - 1` is a multiple of `labels.size()`
  */
  template <typename ConcurrencyTag, typename FeatureRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
  static Ethz_forest train(const FeatureRange& features, const std::vector<int>& labels,
                           std::size_t number_of_labels, std::size_t num_trees, std::size_t max_depth,
                           const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
  {
    namespace RF = CGAL::internal::liblearning::RandomForest;
    if(labels.empty() || features.size() == 0 || (features.size() - 1) % labels.size() != 0)
      throw std::invalid_argument("Ethz_forest::train: " + std::to_string(features.size()) + " values for " +
                                  std::to_string(labels.size()) + " items (one float, then the rows)");
    // RandomForest::train() of CGAL 5.5 with reset trees, no sample indices and seeds from 0, as
    // Random_forest_classifier::train() calls it, with its loop over the trees on the package's loop
    RF::ForestParams params;
    params.n_trees = num_trees;
    params.max_depth = max_depth;
    std::unique_ptr<Forest> forest = std::make_unique<Forest>(params);
    RF::ForestParams& p = forest->params; // the trees point to their forest's parameters
    p.n_classes = number_of_labels;
    p.n_features = (features.size() - 1) / labels.size();
    p.n_samples = labels.size();
    std::vector<int> sample_idxes(p.n_samples);
    for(std::size_t i = 0; i < p.n_samples; ++i)
      sample_idxes[i] = int(i);
    const std::size_t n_idxes = sample_idxes.size();
    p.n_in_bag_samples = n_idxes * (1 - p.sample_reduction); // CGAL's float expression, truncated as CGAL does
    for(std::size_t t = 0; t < p.n_trees; ++t)
      forest->trees.push_back(new Forest::TreeType(&p));
    // the view's element type is not const; nothing writes through it
    const CGAL::internal::liblearning::DataView2D<float> samples(const_cast<float*>(features.data()) + 1,
                                                                 p.n_samples, p.n_features);
    const CGAL::internal::liblearning::DataView2D<int> truth(const_cast<int*>(labels.data()), p.n_samples, 1);
    const RF::AxisAlignedRandomSplitGenerator generator;
    const RF::Tree_training_functor<Forest::TreeType::NodeType, RF::AxisAlignedRandomSplitGenerator> train_tree(
      0, sample_idxes, forest->trees, samples, truth, p.n_in_bag_samples, generator);
    internal::for_each_index<ConcurrencyTag>(
      p.n_trees, internal::number_of_threads(np), [] { return 0; },
      [&](std::size_t t, int&) { train_tree.apply(t); }, 1);
    return Ethz_forest(std::move(forest), number_of_labels, p.n_features);
  }

  /// the number of labels it votes for
  std::size_t number_of_labels() const { return m_labels; }
  /// the number of features it reads
  std::size_t number_of_features() const { return m_features; }

  /// writes the bytes that `Random_forest_classifier::load_configuration()` reads
  void save_configuration(std::ostream& out) const { m_forest->write(out); }

  /*!
    classifies the items `0` ... `n - 1` whose feature `f` at item `i` is `value(i, f)` (converted
    to `float`; a non-finite value becomes `Feature_values::NON_FINITE_VALUE`, as
    `Feature_values` stores it): `label_indices[i]` the first label of the highest vote (0 if all
    votes are 0, as in CGAL's `classify()`), `confidence[j][i]` label `j`'s vote clamped to [0, 1].
    \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `Parallel_if_available_tag`
    \param n the number of items
    \param value `value(i, f)` is convertible to `double`; it is called on several threads at once
    \param label_indices resized to `n`
    \param confidence resized to `number_of_labels()` columns of `n`
    \param np optional: `number_of_threads` (0, the default: all)
  */
  template <typename ConcurrencyTag, typename FeatureValue, typename CGAL_NP_TEMPLATE_PARAMETERS>
  void classify(std::size_t n, const FeatureValue& value, std::vector<int>& label_indices,
                std::vector<std::vector<float>>& confidence,
                const CGAL_NP_CLASS& np = CGAL::parameters::default_values()) const
  {
    label_indices.assign(n, 0);
    confidence.assign(m_labels, std::vector<float>(n, 0.f));
    struct Scratch
    {
      std::vector<float> sample, votes;
    };
    // One float before the sample, 0: CGAL 5.5 leaves the feature of a node whose proposals all
    // failed at -1, and its trees then read the value before the sample.
    internal::for_each_index<ConcurrencyTag>(
      n, internal::number_of_threads(np),
      [&] {
        return Scratch{std::vector<float>(m_features + 1, 0.f), std::vector<float>(m_labels, 0.f)};
      },
      [&](std::size_t i, Scratch& s) {
        for(std::size_t f = 0; f < m_features; ++f)
          s.sample[f + 1] = Feature_values::stored_value(double(value(i, f)));
        m_forest->evaluate(s.sample.data() + 1, s.votes.data());
        float best_value = 0.f;
        for(std::size_t j = 0; j < m_labels; ++j)
        {
          const float v = (std::min)(1.f, (std::max)(0.f, s.votes[j]));
          confidence[j][i] = v;
          if(best_value < v)
          {
            best_value = v;
            label_indices[i] = int(j);
          }
        }
      },
      256);
  }

private:
  Ethz_forest(std::unique_ptr<Forest> forest, std::size_t number_of_labels, std::size_t number_of_features)
    : m_labels(number_of_labels), m_features(number_of_features), m_forest(std::move(forest))
  {
  }

  std::size_t m_labels, m_features;
  std::unique_ptr<Forest> m_forest;
};

} // namespace Classification
} // namespace Sigmoid_neighborhoods
} // namespace CGAL

#endif // CGAL_SIGMOID_NEIGHBORHOODS_CLASSIFICATION_ETHZ_FOREST_H
