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
#include "las_output.h"
#include "phase_times.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iostream>
#include <sstream>
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

// The ASPRS code of each class in a LAS output: --class-codes NAME=CODE,..., else the class's first
// code in the training files (a class trained on codes 3, 4 and 5 is written 3).
std::vector<int> read_class_codes(const Arguments& args, const Label_mapping& labels)
{
  std::vector<int> codes;
  for(const std::vector<int>& c : labels.codes)
    codes.push_back(c.empty() ? 1 : c.front());
  std::stringstream list(args.get("--class-codes"));
  for(std::string item; std::getline(list, item, ',');)
  {
    const std::size_t equal = item.find('=');
    const auto name = std::find(labels.names.begin(), labels.names.end(), item.substr(0, equal));
    int code = -1;
    if(equal != std::string::npos && name != labels.names.end())
    {
      const std::string digits = item.substr(equal + 1);
      if(!digits.empty() && digits.size() <= 3 && digits.find_first_not_of("0123456789") == std::string::npos)
        code = std::stoi(digits);
    }
    if(code < 0 || code > 255)
      throw Usage_error("--class-codes: '" + item + "' is not NAME=CODE with a class of the model (" + labels.text() +
                        ") and a code of 0 to 255");
    codes[std::size_t(name - labels.names.begin())] = code;
  }
  return codes;
}

// The input's records with the predicted class's code as their classification, the class's
// confidence and the record's own classification as extra bytes dimensions (las_output.h); a point
// without a class (its features undefined) is written 1, unclassified.
void write_prediction_las(const std::string& path, const Las_output_points& points, const Featured_file& file,
                          const Prediction& p, const std::vector<int>& codes, unsigned int threads)
{
  typedef Lidar_io::Las_extra_bytes_type Type;
  Las_results r;
  r.dimensions = {{"confidence", "predicted class's confidence", Type::FLOAT},
                  {"original_class", "classification before", Type::UNSIGNED_CHAR}};
  bool checked = false;
  r.complete = [&](unsigned char* record, const Lidar_io::Las_output_layout& l, std::size_t i) {
    if(!checked && !l.has_extended_format())
      for(int code : codes)
        if(code > 31)
          throw Usage_error(file.path + ": point data format " + std::to_string(l.point_format) +
                            " holds classes 0 to 31, and the model writes " + std::to_string(code) +
                            ": give --class-codes NAME=CODE,... of 31 at most");
    checked = true;
    const int c = p.classes[i];
    const std::size_t field = l.has_extended_format() ? 16 : 15;
    const unsigned int original = l.has_extended_format() ? record[16] : (record[15] & 0x1F);
    const unsigned int code = c < 0 ? 1u : unsigned(codes[std::size_t(c)]);
    record[field] = l.has_extended_format() ? std::uint8_t(code) : std::uint8_t((record[15] & 0xE0) | code);
    Lidar_io::store_las_extra(record, l, 0, c < 0 ? 0. : double(p.confidence[std::size_t(c)][i]));
    Lidar_io::store_las_extra(record, l, 1, double(original));
  };
  write_las_results(path, points, file.model, r, threads);
}

// The input's points, or a tile's with a halo: the normals' neighbor rows kept for the features; a
// tile's halo holds them and the grids' cells, and is widened until the pyramid's representatives and
// rows and cgal-metric's neighbors near the tile are checked to be the union's.
Input_points read_points_for_features(const Arguments& args, const Classifier_settings& settings)
{
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
  return in;
}

// The last line: the points of each class, the time of each phase.
void report_prediction(const std::string& output, const Input_points& in, const Prediction& p,
                       const Label_mapping& labels, const Phase_times& times)
{
  std::vector<std::size_t> counts(labels.names.size(), 0);
  for(std::size_t i = in.first; i < in.last; ++i)
    if(p.classes[i] >= 0)
      ++counts[std::size_t(p.classes[i])];
  std::cerr << output << ": " << in.last - in.first << " points" << halo_description(in) << ":";
  for(std::size_t c = 0; c < counts.size(); ++c)
    std::cerr << (c ? ", " : " ") << labels.names[c] << ' ' << counts[c];
  std::cerr << "; " << number_fixed(times.total(), 2) << " s (" << times.text() << ")\n";
}

} // namespace

int run_classify_predict(int argc, char** argv)
{
  const Arguments args(argc, argv, FIRST_COMMAND_ARGUMENT + 1,
                       with_catalog_options({"-o", "--output", "--graphcut", "--threads", "--class-codes"}), {"-h", "--help"});
  if(print_help(args, CLASSIFY_USAGE))
  {
    std::cout << CATALOG_USAGE;
    return EXIT_OK;
  }
  if(args.positional().empty())
    throw Usage_error("classify predict needs MODEL INPUT, or MODEL --catalog SOURCE");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error("classify predict needs -o OUT.ply, -o OUT.las or -o OUT.laz");
  const bool las_output = is_las_output(output);
  if(args.has("--class-codes") && !las_output)
    throw Usage_error("--class-codes goes with -o OUT.las or OUT.laz: a PLY output holds the class indices");
  refuse_las_output_of_catalog(args, "classify predict");
  const std::string& model_path = args.positional()[0];
  std::string forest_bytes;
  Classifier_settings settings = read_classifier_settings(model_path, forest_bytes);
  const std::string model = model_fingerprint(settings, forest_bytes);
  settings.features.threads = settings.normals.threads = read_threads(args);
  const double graphcut = read_graphcut(args);
  const std::vector<int> class_codes = read_class_codes(args, settings.labels);
  if(args.has("--tile"))
    refuse_inexact_tile(settings, graphcut);
  Phase_times times;
  progress("reading");
  Input_points in = read_points_for_features(args, settings);
  if(las_output)
    check_las_output(output, las_output_points(in));
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
  if(las_output)
    write_prediction_las(output, las_output_points(in), file, p, class_codes, settings.features.threads);
  else
    write_prediction_ply(output, file, p, settings.labels, in.first, in.last);
  times.end("writing");
  write_tile_description(output, "classify predict", args, in, times, model);
  end_progress();
  report_prediction(output, in, p, settings.labels, times);
  return EXIT_OK;
}

} // namespace sigmoid_tool
