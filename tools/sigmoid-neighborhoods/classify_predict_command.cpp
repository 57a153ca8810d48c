// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// sigmoid-neighborhoods classify predict: the classes of a point set, or of a catalog's union or one
// of its tiles, under a model file, written as a PLY.

#include "classification/classify_common.h"
#include "classification/feature_groups.h"
#include "classification/feature_options.h"
#include "catalog_input.h"
#include "command_line.h"
#include "phase_times.h"


#include <algorithm>
#include <cstddef>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

using namespace classification; // what the steps share: classification/classify_common.h

namespace {

// What a tile's features or labels cannot share with the union: a refusal naming it, before any reading.
void refuse_inexact_tile(const Classifier_settings& settings, double graphcut)
{
  const std::string groups = whole_set_groups(settings.features);
  if(!groups.empty())
    throw Usage_error("classify predict --tile: the model's feature group " + groups +
                      " depends on the whole point set (cgal takes its scales from the average spacing; models "
                      "trained before the grids were anchored at the origin have CGAL's, anchored at the bounding "
                      "box), so a tile would not get the union's features; predict the union (--catalog without "
                      "--tile), train the model again or use one without it");
  if(graphcut > 0.)
    throw Usage_error("classify predict --tile: --graphcut minimises over the whole point set, so a tile would not "
                      "get the union's labels; predict the union (--catalog without --tile) or leave --graphcut out");
}

// Which model a tile was predicted with, for the tile description: its settings and its trees.
std::string model_fingerprint(const Classifier_settings& settings, const std::string& forest_bytes)
{
  return "model:" + std::to_string(std::hash<std::string>()(settings_json(settings).dump() + forest_bytes));
}

} // namespace

int run_classify_predict(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_catalog_options({"-o", "--output", "--graphcut", "--threads"}), {"-h", "--help"});
  if(print_help(args, CLASSIFY_USAGE))
  {
    std::cout << CATALOG_USAGE;
    return EXIT_OK;
  }
  if(args.positional().empty())
    throw Usage_error("classify predict needs MODEL INPUT, or MODEL --catalog SOURCE");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("classify predict needs -o OUT.ply");
  const std::string& model_path = args.positional()[0];
  std::string forest_bytes;
  Classifier_settings settings = read_classifier_settings(model_path, forest_bytes);
  const std::string model = model_fingerprint(settings, forest_bytes);
  settings.features.threads = settings.normals.threads = read_threads(args);
  const double graphcut = read_graphcut(args);
  if(args.has("--tile"))
    refuse_inexact_tile(settings, graphcut);
  Phase_times times;
  progress("reading");
  // the normals' neighbor rows kept for the features; a tile's halo holds them and the grids' cells,
  // and is widened until the pyramid's representatives and rows and cgal-metric's neighbors near the
  // tile are checked to be the union's
  // --halo WIDTH: the pyramid's first halo too (the cells still hold)
  double minimum_halo = cell_halo(settings.features, !args.has("--halo"));
  Input_points in;
  unsigned int readings = 0;
  for(;;)
  {
    in = read_input_points(args, "classify predict", largest_neighborhood(settings.features), settings.normals,
                           minimum_halo, 1);
    readings += in.halo.readings;
    if(!in.is_tile)
      break;
    const double needed = checked_halo_width_of_tile(in.model, settings.features, in.tile_extent, in.first, in.last);
    if(needed <= in.halo.halo_width)
      break;
    if(readings >= 16)
      throw Usage_error(in.source + ": no halo up to " + number_fixed(in.halo.halo_width, 1) +
                        " holds the neighborhoods near tile " + in.tile_name);
    progress("reading a wider halo for the neighborhoods");
    minimum_halo = std::max(needed, 1.5 * in.halo.halo_width);
  }
  in.halo.readings = readings;
  times.end_reading(in.model);
  if(in.is_tile && in.first == in.last)
    throw Usage_error(in.source + ": tile " + in.tile_name + " has no point of its own (empty, or all on an earlier "
                      "tile's seam): nothing to predict");
  Featured_file file;
  file.path = in.source;
  file.model = std::move(in.model);
  add_features(file, settings.labels, false, settings.features);
  times.end("features");
  const Prediction p = predict(file, settings, forest_bytes, nullptr, graphcut);
  times.end("forest");
  times.move("forest", "forest loading", p.seconds_loading);
  write_prediction_ply(output, file, p, settings.labels, in.first, in.last);
  times.end("writing");
  write_tile_description(output, "classify predict", args, in, times, model);
  end_progress();
  std::vector<std::size_t> counts(settings.labels.names.size(), 0);
  for(std::size_t i = in.first; i < in.last; ++i)
    if(p.classes[i] >= 0)
      ++counts[std::size_t(p.classes[i])];
  std::cerr << output << ": " << in.last - in.first << " points" << halo_description(in) << ":";
  for(std::size_t c = 0; c < counts.size(); ++c)
    std::cerr << (c ? ", " : " ") << settings.labels.names[c] << ' ' << counts[c];
  std::cerr << "; " << number_fixed(times.total(), 2) << " s (" << times.text() << ")\n";
  return EXIT_OK;
}

} // namespace sigmoid_tool
