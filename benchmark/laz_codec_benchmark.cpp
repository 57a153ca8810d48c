// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// LAZ decoding speed: for each file given, the point records decoded (or, for a LAS file, read) on
// each thread count given, the median wall time of a few runs after a warm-up run (the page cache
// warm), in points per second; then the whole read through read_oriented_point_set() (records to
// points and fields, duplicates merged, no normals), which is what a command pays.
// usage: laz_decode_benchmark [--threads 1,2] [--runs 5 (0: one run, no warm-up)] FILE...

#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Lidar_io/read_las_records.h>
#include <Sigmoid_neighborhoods_readers/read_oriented_point_set.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace SN = CGAL::Sigmoid_neighborhoods;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <typename Run>
double median_seconds(unsigned int runs, const Run& run)
{
  if(runs == 0) // one cold run (peak memory)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    return seconds_since(start);
  }
  run(); // warm-up: the file in the page cache
  std::vector<double> times;
  for(unsigned int r = 0; r < runs; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

std::size_t decode_records(const std::string& path, unsigned int threads)
{
  std::size_t checksum = 0;
  Lidar_io::read_las_records(
    path, [&](std::size_t, const unsigned char* r, std::size_t count) {
      checksum += count + r[0]; // keeps the records alive for the optimizer
    },
    threads);
  return checksum;
}

// The bytes of the LAZ file that holds `records` laid out by `layout`, compressed on `threads`.
std::size_t encode_records(const Lidar_io::Las_output_layout& layout, const std::string& records, unsigned int threads)
{
  std::stringstream out;
  Lidar_io::Laz_writer<> writer(out, layout, threads);
  writer.write(reinterpret_cast<const unsigned char*>(records.data()), records.size() / layout.record_length);
  writer.close();
  return std::size_t(out.tellp());
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<unsigned int> thread_counts = {1, 2};
  unsigned int runs = 5;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--threads" && i + 1 < argc)
    {
      thread_counts.clear();
      std::stringstream list(argv[++i]);
      for(std::string t; std::getline(list, t, ',');)
        thread_counts.push_back(unsigned(std::stoul(t)));
    }
    else if(a == "--runs" && i + 1 < argc)
      runs = unsigned(std::stoul(argv[++i]));
    else
      files.push_back(a);
  }
  if(files.empty())
  {
    std::cerr << "usage: laz_decode_benchmark [--threads 1,2] [--runs 5] FILE...\n";
    return 2;
  }
  std::printf("%-52s %9s %7s %10s %10s %13s %10s %10s %11s\n", "file", "points", "threads", "decode_s", "Mpoints/s",
              "read_points_s", "encode_s", "Mpoints/s", "laz_bytes");
  for(const std::string& path : files)
  {
    try
    {
      const Lidar_io::Las_header h = Lidar_io::read_las_header(path);
      std::string records;
      Lidar_io::read_las_records(path, [&](std::size_t, const unsigned char* r, std::size_t count) {
        records.append(reinterpret_cast<const char*>(r), count * h.record_length);
      });
      const Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_like(path, {});
      for(unsigned int t : thread_counts)
      {
        const double decode = median_seconds(runs, [&] { decode_records(path, t); });
        SN::Normal_options options;
        options.neighbors = 0;
        options.threads = t;
        const double read = median_seconds(runs, [&] { SN::read_oriented_point_set(path, options); });
        std::size_t bytes = 0;
        const double encode = median_seconds(runs, [&] { bytes = encode_records(layout, records, t); });
        std::printf("%-52s %9llu %7u %10.4f %10.2f %13.4f %10.4f %10.2f %11zu\n",
                    std::filesystem::path(path).filename().c_str(), static_cast<unsigned long long>(h.point_count), t,
                    decode, double(h.point_count) / decode / 1e6, read, encode,
                    double(h.point_count) / encode / 1e6, bytes);
      }
    }
    catch(const std::exception& e)
    {
      std::cerr << path << ": " << e.what() << '\n';
    }
  }
  return 0;
}
