// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The commands' LAS outputs (las_output.h).

#include "las_output.h"

#include "catalog_input.h"
#include "command_line.h"

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Lidar_io/Las_writer.h>
#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <Lidar_io/read_las_records.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <ios>
#include <limits>
#include <stdexcept>

namespace sigmoid_tool {

namespace SN = CGAL::Sigmoid_neighborhoods;

bool is_las_output(const std::string& path)
{
  const std::string ext = SN::lower_case_extension(path);
  return ext == "las" || ext == "laz";
}

void refuse_las_output_of_catalog(const Arguments& args, const std::string& command)
{
  if(args.has("--catalog") && !args.has("--tile") && is_las_output(args.output()))
    throw Usage_error(command + " --catalog: a LAS output of the catalog's union would mix the records of " +
                      "several files: write one per tile (--tile NAME), or this command's other output");
}

Las_output_points las_output_points(const Input_points& in)
{
  Las_output_points points;
  points.source = in.source;
  if(in.is_tile)
  {
    points.first = in.first;
    points.last = in.last;
    if(!in.halo.point_of_record.empty())
      points.point_of_record = &in.halo.point_of_record;
  }
  return points;
}

void check_las_output(const std::string& path, const Las_output_points& points)
{
  const std::string ext = SN::lower_case_extension(points.source);
  if(SN::lower_case_extension(path) != "laz" || (ext != "las" && ext != "laz"))
    return;
  unsigned int format = 0;
  try
  {
    format = Lidar_io::read_las_header(points.source).point_format;
  }
  catch(const SN::Input_error&)
  {
    return; // reading the input says what is wrong with it
  }
  if(Lidar_io::las_format_has_wave_packets(format))
    throw Usage_error("cannot write " + path + ": LAZ: the wave packets of point format " + std::to_string(format) +
                      " of " + points.source + " are not compressed (write the file as LAS)");
}

namespace {

// One record per point, point format 6: the coordinates at the layout's scale, return 1 of 1, the
// point's label as its classification when it fits (0 to 255), the rest zero.
template <typename Writer>
void write_new_records(Writer& writer, const SN::Oriented_point_set& model, std::size_t begin, std::size_t end,
                       const Las_results& results)
{
  const Lidar_io::Las_output_layout& l = writer.layout();
  constexpr std::size_t BLOCK = 65536;
  std::vector<unsigned char> block;
  for(std::size_t first = begin; first < end; first += BLOCK)
  {
    const std::size_t count = (std::min)(BLOCK, end - first);
    block.assign(count * l.record_length, 0);
    for(std::size_t i = 0; i < count; ++i)
    {
      unsigned char* record = block.data() + i * l.record_length;
      const auto& p = model.points[first + i];
      Lidar_io::store_las_coordinates(record, l, {{p.x(), p.y(), p.z()}});
      record[14] = 0x11;
      if(!model.labels.empty() && model.labels[first + i] >= 0 && model.labels[first + i] <= 255)
        record[16] = std::uint8_t(model.labels[first + i]);
      results.complete(record, l, first + i);
    }
    writer.write(block.data(), count);
  }
}

// The records of the LAS or LAZ file `points.source`, each completed with its point's values.
template <typename Writer>
void write_copied_records(Writer& writer, const Las_output_points& points, const SN::Oriented_point_set& model,
                          const Las_results& results, unsigned int threads)
{
  const Lidar_io::Las_output_layout& l = writer.layout();
  const std::string& source = points.source;
  const std::vector<std::size_t>* point_of = points.point_of_record != nullptr ? points.point_of_record
                                             : model.point_of_input.empty()    ? nullptr
                                                                               : &model.point_of_input;
  const std::size_t inputs = point_of != nullptr ? point_of->size() : model.points.size();
  std::vector<unsigned char> block;
  std::size_t records = 0;
  const Lidar_io::Las_header h = Lidar_io::read_las_records(
    source,
    [&](std::size_t first, const unsigned char* input, std::size_t count) {
      if(first + count > inputs)
        throw Usage_error(source + " holds more records than when it was read: it changed on the way");
      block.assign(count * l.record_length, 0);
      for(std::size_t i = 0; i < count; ++i)
      {
        unsigned char* record = block.data() + i * l.record_length;
        std::memcpy(record, input + i * l.copied_record_length, l.copied_record_length);
        const std::size_t point = point_of != nullptr ? (*point_of)[first + i] : first + i;
        results.complete(record, l, point);
      }
      writer.write(block.data(), count);
      records = first + count;
    },
    threads);
  if(records != inputs || h.point_count != inputs)
    throw Usage_error(source + " holds " + std::to_string(h.point_count) + " records, " + std::to_string(inputs) +
                      " when it was read: it changed on the way");
}

// The files' creation date: SOURCE_DATE_EPOCH's where it is set (files that repeat bit for bit, the
// reproducible-builds convention), otherwise now.
std::time_t creation_time()
{
  if(const char* epoch = std::getenv("SOURCE_DATE_EPOCH"))
    return std::time_t(std::strtoll(epoch, nullptr, 10));
  return std::time(nullptr);
}

} // namespace

void write_las_results(const std::string& path, const Las_output_points& points, const SN::Oriented_point_set& model,
                       const Las_results& results, unsigned int threads)
{
  const std::string& source = points.source;
  const std::string ext = SN::lower_case_extension(source);
  errno = 0;
  try
  {
    const bool compressed = SN::lower_case_extension(path) == "laz";
    // The records, copied or new, go to a LAS or a LAZ writer alike.
    auto write = [&](std::ofstream& out, Lidar_io::Las_output_layout layout, const auto& write_records) {
      if(compressed)
      {
        Lidar_io::Laz_writer<> writer(out, std::move(layout), threads);
        write_records(writer);
        writer.close();
      }
      else
      {
        Lidar_io::Las_writer writer(out, std::move(layout));
        write_records(writer);
        writer.close();
      }
    };
    write_file_atomically(
      path,
      [&](std::ofstream& out) {
        if(ext == "las" || ext == "laz")
        {
          write(out, Lidar_io::las_output_layout_like(source, results.dimensions),
                [&](auto& writer) { write_copied_records(writer, points, model, results, threads); });
          return;
        }
        const std::size_t first = (std::min)(points.first, model.points.size());
        const std::size_t last = (std::max)(first, (std::min)(points.last, model.points.size()));
        std::array<double, 3> min{{0., 0., 0.}}, max{{0., 0., 0.}};
        if(first < last)
        {
          const CGAL::Bbox_3 box = CGAL::bbox_3(model.points.begin() + std::ptrdiff_t(first),
                                                model.points.begin() + std::ptrdiff_t(last));
          min = {{box.xmin(), box.ymin(), box.zmin()}};
          max = {{box.xmax(), box.ymax(), box.zmax()}};
        }
        write(out, Lidar_io::las_output_layout_for(min, max, results.dimensions, 6, creation_time()),
              [&](auto& writer) { write_new_records(writer, model, first, last, results); });
      },
      true);
  }
  catch(const SN::Input_error& e)
  {
    throw Usage_error(source + ": " + e.what());
  }
  catch(const std::ios_base::failure& e)
  {
    // errno still holds the failed write's reason (ENOSPC, EFBIG, EIO...), as write_file_atomically's
    throw Usage_error("cannot write " + path + ": " + (errno != 0 ? std::strerror(errno) : e.what()));
  }
  catch(const std::range_error& e)
  {
    throw Usage_error("cannot write " + path + ": " + e.what());
  }
  catch(const std::length_error& e)
  {
    throw Usage_error("cannot write " + path + ": " + e.what());
  }
  catch(const std::invalid_argument& e) // a LAZ output of records with wave packets
  {
    throw Usage_error("cannot write " + path + ": " + e.what());
  }
}

} // namespace sigmoid_tool
