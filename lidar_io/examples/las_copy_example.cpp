// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Copies the point records of a LAS or LAZ file to a LAS 1.4 or LAZ file, the input's header fields,
// VLRs and EVLRs kept: compresses (OUT.laz, as LASzip does) or decompresses (OUT.las) a survey on
// --threads threads, and adds a dimension that numbers the records when --numbered is given.
// usage: las_copy_example IN.las|IN.laz OUT.las|OUT.laz [--threads N] [--numbered]

#include <Lidar_io/Las_writer.h>
#include <Lidar_io/Laz_writer.h>
#include <Lidar_io/las_output_layout_like.h>
#include <Lidar_io/lower_case_extension.h>
#include <Lidar_io/read_las_records.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

// The records of `input`, each followed by its index when the layout adds a dimension.
template <typename Writer>
void copy_records(const std::string& input, Writer& writer, unsigned int threads)
{
  const Lidar_io::Las_output_layout& layout = writer.layout();
  std::vector<unsigned char> block;
  Lidar_io::read_las_records(
    input,
    [&](std::size_t first, const unsigned char* records, std::size_t count) {
      block.assign(count * layout.record_length, 0);
      for(std::size_t i = 0; i < count; ++i)
      {
        unsigned char* record = block.data() + i * layout.record_length;
        std::memcpy(record, records + i * layout.copied_record_length, layout.copied_record_length);
        if(!layout.added.empty())
          Lidar_io::store_las_extra(record, layout, 0, double(first + i));
      }
      writer.write(block.data(), count);
    },
    threads);
  writer.close();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: las_copy_example IN.las|IN.laz OUT.las|OUT.laz [--threads N] [--numbered]\n";
    return EXIT_FAILURE;
  }
  const std::string input = argv[1], output = argv[2];
  unsigned int threads = 0;
  std::vector<Lidar_io::Las_extra_dimension> added;
  for(int i = 3; i < argc; ++i)
  {
    if(std::string(argv[i]) == "--threads" && i + 1 < argc)
      threads = unsigned(std::stoul(argv[++i]));
    else if(std::string(argv[i]) == "--numbered")
      added.push_back({"record", "the record's index in the input", Lidar_io::Las_extra_bytes_type::UNSIGNED_LONG});
  }
  try
  {
    Lidar_io::Las_output_layout layout = Lidar_io::las_output_layout_like(input, added);
    std::ofstream out(output, std::ios::binary | std::ios::trunc);
    const bool compressed = Lidar_io::lower_case_extension(output) == "laz";
    std::uint64_t records = 0;
    if(compressed)
    {
      Lidar_io::Laz_writer<> writer(out, std::move(layout), threads);
      copy_records(input, writer, threads);
      records = writer.summary().count;
    }
    else
    {
      Lidar_io::Las_writer writer(out, std::move(layout));
      copy_records(input, writer, threads);
      records = writer.summary().count;
    }
    out.close();
    if(!out)
      throw std::ios_base::failure("cannot write " + output);
    std::cout << records << " records written to " << output << (compressed ? " (LAZ)" : " (LAS)") << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << input << ": " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
