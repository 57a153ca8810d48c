// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify experiment: feature sets compared on training and test files, in
// several feature orders, with and without graph-cut, each cross-validated on the training files, and
// the report of it (experiment.md, .csv, .json, runs.csv, the figure of a test file).

#include "classification/classify_common.h"
#include "classification/classify_training.h"
#include "classification/confusion.h"
#include "classification/feature_groups.h"
#include "classification/label_mapping.h"
#include "classification/scale_choice.h"
#include "command_line.h"
#include "model_input.h"

#include <CGAL/Real_timer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

using namespace classification; // what the steps share: classification/classify_common.h

namespace {

// The feature sets of the experiment: what a CGAL user has (A), the fixed scale of pgeof and
// jakteristics (B), the classical optimal neighborhoods (C, D), the package's (E), several scales
// without and with sigmoid weights (F, F_sigmoid), and CGAL's with the package's added (G_*), the
// last two of them the same ablation on top of CGAL's; the scales in metres: the pyramid alone (P*)
// and with CGAL's (H_*), and CGAL's generator on scales in metres (M*).
const char* const DEFAULT_EXPERIMENT_SETS =
  "A=cgal;B=k20,height;C=eigenentropy,height;D=dimensionality,height;E=optimal,height;F=multiscale,height;"
  "F_sigmoid=multiscale-sigmoid,height;G_optimal=cgal,optimal;G_multiscale=cgal,multiscale;"
  "G_multiscale_sigmoid=cgal,multiscale-sigmoid;P=pyramid;P_sigmoid=pyramid-sigmoid;H_pyramid=cgal,pyramid;"
  "H_pyramid_sigmoid=cgal,pyramid-sigmoid;M=cgal-metric;M_multiscale_sigmoid=cgal-metric,multiscale-sigmoid;"
  "M_multiscale_sigmoid_pyramid=cgal-metric,multiscale-sigmoid,pyramid;"
  "N_multiscale_sigmoid_pyramid_height=multiscale-sigmoid,pyramid,height;"
  "Q_grid_multiscale_sigmoid_pyramid_height=cgal-grid,multiscale-sigmoid,pyramid,height";

struct Feature_set_spec
{
  std::string name;
  std::vector<std::string> groups;
  // --choose-scales: the first scale in metres chosen for this set on the training files (sets
  // without scales in metres keep the options')
  std::optional<Scale_choice_report> scale_choice;
};

// A group as computed for a set: at the set's chosen first scale in metres where it has scales in
// metres, else with the options alone.
struct Group_at_scale
{
  std::string group;
  double first_scale = 0.; // 0: the options' scales

  std::string key() const { return first_scale > 0. ? group + " at " + number17(first_scale) + " m" : group; }
};

std::vector<Group_at_scale> groups_at_scales(const Feature_set_spec& set)
{
  std::vector<Group_at_scale> groups;
  for(const std::string& g : set.groups)
  {
    const Feature_group* entry = find_feature_group(g);
    groups.push_back({g, set.scale_choice && entry->metric_scales ? set.scale_choice->chosen : 0.});
  }
  return groups;
}

// The options a set's forest is trained and its groups computed with.
Feature_options set_options(const Feature_options& base, const Feature_set_spec& set)
{
  Feature_options o = set.scale_choice ? with_first_scale(base, set.scale_choice->chosen) : base;
  o.groups = set.groups;
  return o;
}

std::vector<Feature_set_spec> parse_sets(const std::string& text)
{
  std::vector<Feature_set_spec> sets;
  for(const std::string& item : split(text, ';'))
  {
    const std::size_t equals = item.find('=');
    if(equals == std::string::npos || equals == 0)
      throw Usage_error("--sets: expected NAME=GROUP[,GROUP...], got '" + item + "'");
    sets.push_back({item.substr(0, equals), parse_feature_groups(item.substr(equals + 1))});
  }
  return sets;
}

std::vector<std::string> split_list(const std::string& text, const std::string& option)
{
  std::vector<std::string> items;
  for(const std::string& item : split(text, ','))
    if(!item.empty())
      items.push_back(item);
  if(items.empty())
    throw Usage_error(option + " needs at least one file");
  return items;
}

// One file of the experiment: read once, each feature group computed once per scale (and timed), the
// sets' columns assembled from the groups (keyed by Group_at_scale::key()).
struct Experiment_file
{
  Featured_file file; // columns empty: see groups
  std::map<std::string, std::vector<Feature_column>> groups;
  std::map<std::string, double> seconds;
};

Experiment_file read_experiment_file(const std::string& path, const Label_mapping& labels,
                                     const SN::Normal_options& normals, const Feature_options& base,
                                     const std::vector<Group_at_scale>& groups)
{
  Experiment_file e;
  Feature_options all = base;
  for(const Group_at_scale& g : groups)
    if(std::find(all.groups.begin(), all.groups.end(), g.group) == all.groups.end())
      all.groups.push_back(g.group); // the neighbor rows do not depend on the scales in metres
  // read with the rows of every group kept, then no group: each is computed and timed below, on those rows
  e.file = read_and_feature(path, labels, true, normals, all, false);
  for(const Group_at_scale& g : groups)
  {
    Feature_options one = g.first_scale > 0. ? with_first_scale(base, g.first_scale) : base;
    one.groups = {g.group};
    CGAL::Real_timer timer;
    timer.start();
    e.groups[g.key()] = compute_feature_columns(e.file.model, one, [&](const std::string& step) {
      progress(path + ": " + step);
    });
    e.seconds[g.key()] = timer.time();
  }
  return e;
}

Featured_file with_set(const Experiment_file& e, const Feature_set_spec& set)
{
  Featured_file f;
  f.path = e.file.path;
  f.model.points = e.file.model.points; // for graph-cut's neighborhoods
  f.model.labels = e.file.model.labels;
  f.truth = e.file.truth;
  // each group was computed alone: a column that an earlier group of the set gave (the heights of both
  // pyramid groups, the equal-weight levels of pyramid-sigmoid beside pyramid) is kept once, as train
  // computes the set
  std::set<std::string> names;
  for(const Group_at_scale& g : groups_at_scales(set))
  {
    for(const Feature_column& c : e.groups.at(g.key()))
      if(names.insert(c.name).second)
        f.columns.push_back(c);
    f.seconds_features += e.seconds.at(g.key());
  }
  return f;
}

struct Run_result
{
  std::string set;
  unsigned int order = 0;
  bool graphcut = false;
  Confusion confusion{0};
  double train_seconds = 0., classify_seconds = 0.;
  std::vector<int> first_test_file; // its classes, kept for the figure (order 1 without graph-cut)
};

struct Set_summary
{
  std::string set;
  bool graphcut = false;
  std::size_t features = 0;
  double miou_mean = 0., miou_min = 0., miou_max = 0., oa_mean = 0., mf1_mean = 0.;
  std::vector<double> class_iou_mean;
  double feature_seconds = 0., train_seconds = 0., classify_seconds = 0.;
  double cross_validated_miou = std::numeric_limits<double>::quiet_NaN(); // on the training files
};

// Mean IoU of leaving each training file out in turn, per (set, graph-cut): the choice of a set is
// made on these, never on the test files.
typedef std::map<std::pair<std::string, bool>, double> Cross_validation;

std::vector<Set_summary> summarize(const std::vector<Feature_set_spec>& sets, const std::vector<Run_result>& runs,
                                   const std::vector<Experiment_file>& train_files,
                                   const std::vector<Experiment_file>& test_files, std::size_t classes)
{
  std::vector<Set_summary> result;
  for(const Feature_set_spec& set : sets)
    for(bool graphcut : {false, true})
    {
      Set_summary s;
      s.set = set.name;
      s.graphcut = graphcut;
      s.class_iou_mean.assign(classes, 0.);
      s.miou_min = std::numeric_limits<double>::infinity();
      s.miou_max = -s.miou_min;
      std::size_t n = 0;
      for(const Run_result& r : runs)
        if(r.set == set.name && r.graphcut == graphcut)
        {
          const double miou = r.confusion.mean_iou();
          s.miou_mean += miou;
          s.miou_min = std::min(s.miou_min, miou);
          s.miou_max = std::max(s.miou_max, miou);
          s.oa_mean += r.confusion.overall_accuracy();
          s.mf1_mean += r.confusion.mean_f1();
          for(std::size_t c = 0; c < classes; ++c)
            s.class_iou_mean[c] += r.confusion.iou(c);
          s.train_seconds += r.train_seconds;
          s.classify_seconds += r.classify_seconds;
          ++n;
        }
      if(n == 0)
        continue;
      s.miou_mean /= double(n);
      s.oa_mean /= double(n);
      s.mf1_mean /= double(n);
      for(double& v : s.class_iou_mean)
        v /= double(n);
      s.train_seconds /= double(n);
      s.classify_seconds /= double(n);
      for(const auto* files : {&train_files, &test_files})
        for(const Experiment_file& e : *files)
          for(const Group_at_scale& g : groups_at_scales(set))
            s.feature_seconds += e.seconds.at(g.key());
      if(!train_files.empty())
        s.features = with_set(train_files.front(), set).columns.size();
      result.push_back(std::move(s));
    }
  return result;
}

// What classify experiment is asked for.
struct Experiment_options
{
  std::string output;
  std::vector<std::string> train_paths, test_paths;
  std::vector<Feature_set_spec> sets;
  unsigned int orders = 10, cv_orders = 1;
  double graphcut = 0.2;
  Classifier_settings base; // the groups are each set's
  bool choose_scales = false;
};

const Feature_set_spec& spec_of(const std::vector<Feature_set_spec>& sets, const std::string& name)
{
  return *std::find_if(sets.begin(), sets.end(), [&](const Feature_set_spec& set) { return set.name == name; });
}

std::size_t labeled_points(const std::vector<Experiment_file>& files)
{
  std::size_t labeled = 0;
  for(const Experiment_file& e : files)
    for(int t : e.file.truth)
      labeled += t >= 0;
  return labeled;
}

// The files' names, in backquotes, comma-separated.
std::string file_names(const std::vector<Experiment_file>& files)
{
  std::string s;
  for(const Experiment_file& e : files)
    s += (s.empty() ? "" : ", ") + std::string("`") + std::filesystem::path(e.file.path).filename().string() + "`";
  return s;
}

// runs.csv: the scores of every run.
void write_runs_csv(const std::string& dir, const std::vector<Run_result>& runs, const Label_mapping& m)
{
  write_file_atomically(dir + "/runs.csv", [&](std::ofstream& out) {
    out << "set,order,graphcut,overall_accuracy,mean_f1,mean_iou";
    for(const std::string& name : m.names)
      out << ",iou_" << name;
    out << ",train_seconds,classify_seconds\n";
    for(const Run_result& r : runs)
    {
      out << r.set << ',' << r.order << ',' << (r.graphcut ? 1 : 0) << ',' << number17(r.confusion.overall_accuracy())
          << ',' << number17(r.confusion.mean_f1()) << ',' << number17(r.confusion.mean_iou());
      for(std::size_t c = 0; c < m.names.size(); ++c)
        out << ',' << number17(r.confusion.iou(c));
      out << ',' << number_fixed(r.train_seconds, 3) << ',' << number_fixed(r.classify_seconds, 3) << '\n';
    }
  });
}

// experiment.csv: a row per set and graph-cut.
void write_experiment_csv(const std::string& dir, const std::vector<Feature_set_spec>& sets,
                          const std::vector<Set_summary>& summaries, const Label_mapping& m)
{
  write_file_atomically(dir + "/experiment.csv", [&](std::ofstream& out) {
    out << "set,groups,graphcut,features,mean_iou_mean,mean_iou_min,mean_iou_max,overall_accuracy_mean,mean_f1_mean";
    for(const std::string& name : m.names)
      out << ",iou_" << name << "_mean";
    out << ",feature_seconds,train_seconds_mean,classify_seconds_mean,cross_validated_mean_iou,chosen_first_scale\n";
    for(const Set_summary& s : summaries)
    {
      std::string groups;
      for(const Feature_set_spec& set : sets)
        if(set.name == s.set)
          for(const std::string& g : set.groups)
            groups += (groups.empty() ? "" : "+") + g;
      out << s.set << ',' << groups << ',' << (s.graphcut ? 1 : 0) << ',' << s.features << ','
          << number17(s.miou_mean) << ',' << number17(s.miou_min) << ',' << number17(s.miou_max) << ','
          << number17(s.oa_mean) << ',' << number17(s.mf1_mean);
      for(double v : s.class_iou_mean)
        out << ',' << number17(v);
      out << ',' << number_fixed(s.feature_seconds, 2) << ',' << number_fixed(s.train_seconds, 2) << ','
          << number_fixed(s.classify_seconds, 2) << ','
          << (std::isnan(s.cross_validated_miou) ? std::string() : number17(s.cross_validated_miou)) << ','
          << (spec_of(sets, s.set).scale_choice ? number17(spec_of(sets, s.set).scale_choice->chosen) : std::string())
          << '\n';
    }
  });
}

// experiment.json: the settings, the chosen set and every set's summary.
void write_experiment_json(const Experiment_options& o, const std::vector<Experiment_file>& train_files,
                           const std::vector<Experiment_file>& test_files, const std::vector<Set_summary>& summaries,
                           const Set_summary* chosen)
{
  const Label_mapping& m = o.base.labels;
  nlohmann::json j;
  j["labels"] = m.text();
  j["train"] = nlohmann::json::array();
  for(const Experiment_file& e : train_files)
    j["train"].push_back(e.file.path);
  for(const Experiment_file& e : test_files)
    j["test"].push_back(e.file.path);
  j["orders"] = o.orders;
  j["graphcut_strength"] = o.graphcut;
  j["trees"] = o.base.trees;
  j["depth"] = o.base.depth;
  j["normals"] = settings_json(o.base)["normals"];
  j["cross_validation_orders"] = o.cv_orders;
  if(chosen != nullptr)
    j["chosen"] = {{"set", chosen->set}, {"graphcut", chosen->graphcut}};
  for(const Set_summary& s : summaries)
  {
    nlohmann::json row = {{"set", s.set},          {"graphcut", s.graphcut},     {"features", s.features},
                          {"mean_iou", {{"mean", s.miou_mean}, {"min", s.miou_min}, {"max", s.miou_max}}},
                          {"overall_accuracy_mean", s.oa_mean}, {"mean_f1_mean", s.mf1_mean},
                          {"feature_seconds", s.feature_seconds}, {"train_seconds_mean", s.train_seconds},
                          {"classify_seconds_mean", s.classify_seconds}};
    if(!std::isnan(s.cross_validated_miou))
      row["cross_validated_mean_iou"] = s.cross_validated_miou;
    if(const std::optional<Scale_choice_report>& c = spec_of(o.sets, s.set).scale_choice)
      row["scale_choice"] = scale_choice_json(*c);
    for(std::size_t c = 0; c < m.names.size(); ++c)
      row["iou_mean"][m.names[c]] = s.class_iou_mean[c];
    j["sets"].push_back(row);
  }
  write_file_atomically(o.output + "/experiment.json", [&](std::ofstream& out) { out << j.dump(2) << '\n'; });
}

// The table of experiment.md: a row per set and graph-cut.
void write_set_table(std::ostream& out, const std::vector<Feature_set_spec>& sets,
                     const std::vector<Set_summary>& summaries, const Label_mapping& m)
{
  out << "| set | groups | graph-cut | features | mean IoU | OA | mean F1 |";
  for(const std::string& name : m.names)
    out << " IoU " << name << " |";
  out << " features + train + classify | cross-validated mean IoU |\n|---|---|---|---:|---|---:|---:|";
  for(std::size_t c = 0; c < m.names.size(); ++c)
    out << "---:|";
  out << "---:|---:|\n";
  for(const Set_summary& s : summaries)
  {
    const Feature_set_spec& spec = spec_of(sets, s.set);
    std::string groups;
    for(const std::string& g : spec.groups)
      groups += (groups.empty() ? "" : " + ") + g;
    if(spec.scale_choice)
      groups += ", first scale " + number17(spec.scale_choice->chosen) + " m (chosen)";
    out << "| " << s.set << " | " << groups << " | " << (s.graphcut ? "yes" : "no") << " | " << s.features << " | "
        << fixed3(s.miou_mean) << " [" << fixed3(s.miou_min) << ", " << fixed3(s.miou_max) << "] | "
        << percent(s.oa_mean) << " | " << fixed3(s.mf1_mean) << " |";
    for(double v : s.class_iou_mean)
      out << ' ' << fixed3(v) << " |";
    out << ' ' << number_fixed(s.feature_seconds, 1) << " + " << number_fixed(s.train_seconds, 1) << " + "
        << number_fixed(s.classify_seconds, 1) << " s | " << fixed3(s.cross_validated_miou) << " |\n";
  }
}

// The table of the first scales in metres chosen with --choose-scales, when a set has one.
void write_scale_choice_table(std::ostream& out, const std::vector<Feature_set_spec>& sets)
{
  bool first = true;
  for(const Feature_set_spec& set : sets)
    if(set.scale_choice)
    {
      const Scale_choice_report& c = *set.scale_choice;
      if(first)
      {
        out << "\nThe first scale in metres of the sets with such scales, chosen on the training files alone "
               "(--choose-scales, as classify train chooses it: two folds of a 4 x 4 checkerboard, at most "
            << c.cap << " training points a class and fold; mean IoU at the files' density / trained on a copy "
                        "thinned 4x, the worse of the two decides):\n\n| set | ";
        for(double scale : c.ladder)
          out << number17(scale) << " m | ";
        out << "chosen | time |\n|---|";
        for(std::size_t i = 0; i <= c.ladder.size() + 1; ++i)
          out << "---:|";
        out << '\n';
        first = false;
      }
      out << "| " << set.name << " | ";
      for(std::size_t i = 0; i < c.ladder.size(); ++i)
        out << fixed3(c.same_density[i]) << " / " << fixed3(c.thinned[i]) << " | ";
      out << "**" << number17(c.chosen) << " m** | " << number_fixed(c.seconds, 1) << " s |\n";
    }
}

// experiment.md: the settings, the table of the sets, the chosen set, the chosen scales.
void write_experiment_markdown(const Experiment_options& o, const std::vector<Experiment_file>& train_files,
                               const std::vector<Experiment_file>& test_files,
                               const std::vector<Set_summary>& summaries, const Set_summary* chosen)
{
  const Classifier_settings& base = o.base;
  write_file_atomically(o.output + "/experiment.md", [&](std::ofstream& out) {
    out << "# Classification experiment\n\n"
        << "CGAL's ETHZ random forest (" << base.trees << " trees, depth " << base.depth << "), trained on "
        << file_names(train_files) << " (" << labeled_points(train_files) << " labeled points), tested on "
        << file_names(test_files) << " (" << labeled_points(test_files) << "); classes " << base.labels.text()
        << ", other codes ignored. Every set in " << o.orders
        << " feature orders (the forest depends on the order): mean IoU as mean [min, max]; the other scores are "
           "means. Graph-cut: CGAL's classify_with_graphcut, strength "
        << number_fixed(o.graphcut, 2) << ", 12 neighbors. Times: features of all files, training and "
           "classification (one order); the features' time leaves out the reading, the normals and the "
           "neighbor rows that every set shares (benchmark/classification_speed.sh times a whole prediction).\n\n";
    write_set_table(out, o.sets, summaries, base.labels);
    if(chosen != nullptr)
      out << "\nChosen on the training files alone (the best cross-validated mean IoU: each training file left out "
             "in turn, the forest trained on the others, "
          << o.cv_orders << " order" << (o.cv_orders == 1 ? "" : "s") << "): **" << chosen->set << "**, "
          << (chosen->graphcut ? "with" : "without") << " graph-cut, which scores " << fixed3(chosen->miou_mean)
          << " [" << fixed3(chosen->miou_min) << ", " << fixed3(chosen->miou_max) << "] on the test files.\n";
    write_scale_choice_table(out, o.sets);
  });
}

void write_experiment(const Experiment_options& o, const std::vector<Experiment_file>& train_files,
                      const std::vector<Experiment_file>& test_files, const std::vector<Run_result>& runs,
                      const Cross_validation& cross_validation)
{
  const Label_mapping& m = o.base.labels;
  std::vector<Set_summary> summaries = summarize(o.sets, runs, train_files, test_files, m.names.size());
  const Set_summary* chosen = nullptr;
  for(Set_summary& s : summaries)
  {
    const auto it = cross_validation.find({s.set, s.graphcut});
    if(it != cross_validation.end())
      s.cross_validated_miou = it->second;
  }
  for(const Set_summary& s : summaries)
    if(!std::isnan(s.cross_validated_miou) && (chosen == nullptr || s.cross_validated_miou > chosen->cross_validated_miou))
      chosen = &s;
  write_runs_csv(o.output, runs, m);
  write_experiment_csv(o.output, o.sets, summaries, m);
  write_experiment_json(o, train_files, test_files, summaries, chosen);
  write_experiment_markdown(o, train_files, test_files, summaries, chosen);
  std::cerr << o.output << "/experiment.md: " << o.sets.size() << " feature sets, " << o.orders << " orders, "
            << runs.size() << " runs\n";
}

// The first test file seen from above, by the truth, by the first set and by the set of best mean
// IoU without graph-cut (order 1), and their errors: DIR/figure_tile.csv and DIR/figure_tile.png.
bool write_experiment_figure(const std::string& dir, const std::vector<Feature_set_spec>& sets,
                             const Experiment_file& tile, const std::vector<Run_result>& runs, const Label_mapping& m)
{
  const std::vector<Set_summary> summaries =
    summarize(sets, runs, std::vector<Experiment_file>{}, std::vector<Experiment_file>{}, m.names.size());
  std::string best;
  double best_iou = -1.;
  for(const Set_summary& s : summaries)
    if(!s.graphcut && s.set != sets.front().name && s.miou_mean > best_iou)
    {
      best_iou = s.miou_mean;
      best = s.set;
    }
  std::vector<std::string> shown{sets.front().name};
  if(!best.empty())
    shown.push_back(best);
  std::vector<const std::vector<int>*> predictions;
  for(const std::string& name : shown)
    for(const Run_result& r : runs)
      if(r.set == name && r.order == 1 && !r.graphcut)
        predictions.push_back(&r.first_test_file);
  const std::string csv = dir + "/figure_tile.csv";
  write_file_atomically(csv, [&](std::ofstream& out) {
    out << "x,y,z,truth";
    for(const std::string& name : shown)
      out << ',' << name;
    out << '\n';
    for(std::size_t i = 0; i < tile.file.model.points.size(); ++i)
    {
      const auto& p = tile.file.model.points[i];
      out << number17(p.x()) << ',' << number17(p.y()) << ',' << number17(p.z()) << ',' << tile.file.truth[i];
      for(const auto* prediction : predictions)
        out << ',' << (*prediction)[i];
      out << '\n';
    }
  });
  std::string classes;
  for(const std::string& name : m.names)
    classes += (classes.empty() ? "" : ",") + name;
  const std::string title = std::filesystem::path(tile.file.path).filename().string() + ": truth, " +
                            shown.front() + (best.empty() ? "" : " and " + best) + " (order 1, no graph-cut)";
  if(!run_python_script("plot_classification.py", {csv, dir + "/figure_tile.png", "--classes", classes, "--title", title}))
  {
    std::cerr << "sigmoid-neighborhoods classify: the figure failed (plot_classification.py, matplotlib); "
              << csv << " holds its data\n";
    return false;
  }
  return true;
}

Experiment_options read_experiment_options(const Arguments& args)
{
  Experiment_options o;
  o.output = args.output();
  if(o.output.empty() || !args.has("--train") || !args.has("--test") || !args.positional().empty())
    throw Usage_error("classify experiment needs --train FILE,... --test FILE,... -o DIR");
  o.train_paths = split_list(args.get("--train"), "--train");
  o.test_paths = split_list(args.get("--test"), "--test");
  o.sets = parse_sets(args.get("--sets", DEFAULT_EXPERIMENT_SETS));
  o.orders = args.get_unsigned("--orders", 10);
  o.cv_orders = args.get_unsigned("--cv-orders", 1);
  o.graphcut = args.has("--graphcut") ? read_graphcut(args) : 0.2;
  if(o.orders < 1)
    throw Usage_error("--orders must be at least 1");
  Classifier_settings& base = o.base;
  base.labels = parse_label_mapping(args.get("--labels", DEFAULT_LABELS));
  base.normals = classify_normal_options(args);
  base.features = read_feature_options(args); // the groups are each set's
  base.trees = args.get_unsigned("--trees", 25);
  base.depth = args.get_unsigned("--depth", 20);
  base.max_per_class = args.get_unsigned("--max-per-class", 0);
  o.choose_scales = args.has("--choose-scales");
  if(o.choose_scales && (args.has("--cgal-voxel") || args.has("--pyramid-cell")))
    throw Usage_error("--choose-scales chooses --cgal-voxel and --pyramid-cell: give them or it");
  if(o.choose_scales && std::none_of(o.sets.begin(), o.sets.end(), [&](const Feature_set_spec& set) {
       return has_metric_scales(set_options(base.features, set));
     }))
    throw Usage_error("--choose-scales: no set of --sets has a group with scales in metres (cgal-metric, cgal-grid, "
                      "pyramid, pyramid-sigmoid)");
  return o;
}

// --choose-scales: each set with scales in metres gets the choice that classify train would make for it.
void choose_set_scales(Experiment_options& o)
{
  for(Feature_set_spec& set : o.sets)
  {
    Classifier_settings s = o.base;
    s.features = set_options(o.base.features, set);
    if(!has_metric_scales(s.features))
      continue;
    progress(set.name + ": choosing the scales in metres");
    set.scale_choice = choose_first_scale(o.train_paths, s);
  }
}

// The groups of all sets, each at each of its scales once.
std::vector<Group_at_scale> groups_of_all_sets(const std::vector<Feature_set_spec>& sets)
{
  std::vector<Group_at_scale> groups;
  for(const Feature_set_spec& set : sets)
    for(const Group_at_scale& g : groups_at_scales(set))
      if(std::none_of(groups.begin(), groups.end(), [&](const Group_at_scale& h) { return h.key() == g.key(); }))
        groups.push_back(g);
  return groups;
}

// The forest of `set` in the feature order `order`, trained on `files`.
void train_set(const Experiment_options& o, const Feature_set_spec& set, unsigned int order,
               const std::vector<Featured_file>& files, Trained& t)
{
  t.settings = o.base;
  t.settings.features = set_options(o.base.features, set);
  t.settings.feature_order_seed = order;
  train(files, t);
}

// Every set in every order trained on the training files and tested on the test files, without
// and with graph-cut (--graphcut 0: without alone, with it they would be the same).
std::vector<Run_result> run_sets(const Experiment_options& o, const std::vector<Experiment_file>& train_files,
                                 const std::vector<Experiment_file>& test_files)
{
  const std::size_t graphcut_variants = o.graphcut > 0. ? 2 : 1;
  std::vector<Run_result> runs;
  for(const Feature_set_spec& set : o.sets)
  {
    std::vector<Featured_file> train_set_files, test_set;
    for(const Experiment_file& e : train_files)
      train_set_files.push_back(with_set(e, set));
    for(const Experiment_file& e : test_files)
      test_set.push_back(with_set(e, set));
    for(unsigned int order = 1; order <= o.orders; ++order)
    {
      progress(set.name + ": order " + std::to_string(order) + " of " + std::to_string(o.orders));
      Trained t;
      train_set(o, set, order, train_set_files, t);
      for(std::size_t variant = 0; variant < graphcut_variants; ++variant)
      {
        const bool with_graphcut = variant == 1;
        Run_result r;
        r.set = set.name;
        r.order = order;
        r.graphcut = with_graphcut;
        r.confusion = Confusion(o.base.labels.names.size());
        r.train_seconds = t.seconds;
        for(const Featured_file& f : test_set)
        {
          const Prediction p = predict(f, t.settings, std::string(), &*t.forest, with_graphcut ? o.graphcut : 0.);
          r.classify_seconds += p.seconds;
          for(std::size_t i = 0; i < p.classes.size(); ++i)
            r.confusion.add(f.truth[i], p.classes[i]);
          if(order == 1 && !with_graphcut && &f == &test_set.front())
            r.first_test_file = p.classes;
        }
        runs.push_back(std::move(r));
      }
    }
  }
  return runs;
}

// Leave one training file out: what the choice of a set and of the graph-cut is made on.
Cross_validation cross_validate(const Experiment_options& o, const std::vector<Experiment_file>& train_files)
{
  const std::size_t graphcut_variants = o.graphcut > 0. ? 2 : 1;
  const std::size_t classes = o.base.labels.names.size();
  Cross_validation cross_validation;
  if(train_files.size() < 2)
    return cross_validation;
  for(const Feature_set_spec& set : o.sets)
  {
    std::array<double, 2> sum{{0., 0.}};
    for(unsigned int order = 1; order <= o.cv_orders; ++order)
    {
      std::array<Confusion, 2> pooled{{Confusion(classes), Confusion(classes)}};
      for(std::size_t left_out = 0; left_out < train_files.size(); ++left_out)
      {
        progress(set.name + ": cross-validation, order " + std::to_string(order) + ", fold " +
                 std::to_string(left_out + 1));
        std::vector<Featured_file> others;
        for(std::size_t f = 0; f < train_files.size(); ++f)
          if(f != left_out)
            others.push_back(with_set(train_files[f], set));
        Trained t;
        train_set(o, set, order, others, t);
        const Featured_file held_out = with_set(train_files[left_out], set);
        for(std::size_t with_graphcut = 0; with_graphcut < graphcut_variants; ++with_graphcut)
        {
          const Prediction p = predict(held_out, t.settings, std::string(), &*t.forest,
                                       with_graphcut ? o.graphcut : 0.);
          for(std::size_t i = 0; i < p.classes.size(); ++i)
            pooled[with_graphcut].add(held_out.truth[i], p.classes[i]);
        }
      }
      for(std::size_t g = 0; g < graphcut_variants; ++g)
        sum[g] += pooled[g].mean_iou();
    }
    for(std::size_t g = 0; g < graphcut_variants; ++g)
      if(o.cv_orders > 0)
        cross_validation[{set.name, g == 1}] = sum[g] / double(o.cv_orders);
  }
  return cross_validation;
}

} // namespace

int run_classify_experiment(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_feature_options(with_normal_options({"-o", "--output", "--train", "--test", "--sets",
                                                                 "--orders", "--graphcut", "--labels", "--trees",
                                                                 "--depth", "--cv-orders", "--max-per-class"})),
                       with_normal_flags({"-h", "--help", "--choose-scales"}), NORMAL_TRIPLE_OPTIONS);
  if(print_help(args, CLASSIFY_USAGE))
    return EXIT_OK;
  Experiment_options o = read_experiment_options(args);
  create_output_folder(o.output);
  if(o.choose_scales)
    choose_set_scales(o);
  const std::vector<Group_at_scale> groups = groups_of_all_sets(o.sets);
  std::vector<Experiment_file> train_files, test_files;
  for(const std::string& path : o.train_paths)
    train_files.push_back(read_experiment_file(path, o.base.labels, o.base.normals, o.base.features, groups));
  for(const std::string& path : o.test_paths)
    test_files.push_back(read_experiment_file(path, o.base.labels, o.base.normals, o.base.features, groups));

  const std::vector<Run_result> runs = run_sets(o, train_files, test_files);
  const Cross_validation cross_validation = cross_validate(o, train_files);
  end_progress();
  write_experiment(o, train_files, test_files, runs, cross_validation);
  return write_experiment_figure(o.output, o.sets, test_files.front(), runs, o.base.labels) ? EXIT_OK : EXIT_FAILED;
}

} // namespace sigmoid_tool
