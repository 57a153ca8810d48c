// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the subcommands share: option parsing and validation, exit codes, reading an input with a
// one-line error, output folders and atomic output files, numbers, and running the plotting scripts.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
#define SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H

#include "tool_paths.h"

#include <Sigmoid_neighborhoods_readers/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/defaults.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace sigmoid_tool {

namespace fs = std::filesystem;

enum Exit_code
{
  EXIT_OK = 0,
  EXIT_FAILED = 1,   // an unexpected internal error
  EXIT_BAD_INPUT = 2 // bad usage, unreadable or unusable input, unwritable output
};

// An error the user can fix; its message is one line.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// argv[0] is the program and argv[1] the command: a command's own arguments start here.
constexpr int FIRST_COMMAND_ARGUMENT = 2;

// `--name value` options (`--name X Y Z` for the ones in `triples`) and positional arguments;
// every option must be known.
class Arguments
{
public:
  Arguments(int argc, char** argv, int first, const std::vector<std::string>& valued,
            const std::vector<std::string>& flags = {}, const std::vector<std::string>& triples = {});

  const std::vector<std::string>& positional() const { return m_positional; }
  const std::map<std::string, std::string>& options() const { return m_options; }
  bool has(const std::string& name) const { return m_options.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = std::string()) const
  {
    auto it = m_options.find(name);
    return it == m_options.end() ? fallback : it->second;
  }

  double get_double(const std::string& name, double fallback) const;

  // The three numbers of an option of `triples`.
  std::vector<double> get_doubles(const std::string& name) const;

  // Integer options are counts: sizes, iterations, threads; a larger one is a typing error.
  static constexpr long LARGEST_UNSIGNED_OPTION = 1000000;

  unsigned int get_unsigned(const std::string& name, unsigned int fallback) const;

  // `-o PATH` or `--output PATH`; empty when absent.
  std::string output() const { return get("-o", get("--output")); }

private:
  static bool contains(const std::vector<std::string>& v, const std::string& s)
  {
    for(const auto& x : v)
      if(x == s)
        return true;
    return false;
  }
  static bool is_number(const std::string& s);

  std::map<std::string, std::string> m_options;
  std::vector<std::string> m_positional;
};

// Prints `usage` when -h or --help is given: the command then returns EXIT_OK.
bool print_help(const Arguments& args, const char* usage);

// The INPUT and the -o OUTPUT of a command on one model; `output_description` names what -o takes.
std::pair<std::string, std::string> one_input_and_output(const Arguments& args, const std::string& command,
                                                                const std::string& output_description);

// --threads N: the threads of every parallel call (0: OpenMP's default).
inline unsigned int read_threads(const Arguments& args) { return args.get_unsigned("--threads", 0); }

// The number of threads that `--threads requested` stands for: OpenMP's default for 0.
unsigned int resolved_threads(unsigned int requested);

// --angle-tolerance: a tolerance on angles in radians, in [0, pi).
double read_angle_tolerance(const Arguments& args, double fallback);

// An option of comma-separated angles in [0, pi]: radians (`1.5`, `pi`) or degrees (`30deg`),
// sorted and deduplicated as the library does. Multiples of 30deg are the default grid's values
// bit for bit, so that `0,30deg,...,180deg` is the default grid.
std::vector<double> read_angle_list(const Arguments& args, const std::string& name,
                                           const std::vector<double>& fallback);

// The pieces of `text` between the separators `separator` (empty pieces included: "a,,b" has three).
std::vector<std::string> split(const std::string& text, char separator);

// Runs `read()`; a file it cannot use (Input_error) becomes a Usage_error that names `path`.
template <typename Read>
auto read_input(const std::string& path, const Read& read) -> decltype(read())
{
  try
  {
    return read();
  }
  catch(const CGAL::Sigmoid_neighborhoods::Input_error& e)
  {
    throw Usage_error(path + ": " + e.what());
  }
}

// The indices 0, ..., n - 1: the point range of the library calls over a model's points.
std::vector<std::uint32_t> point_indices(std::size_t n);

// 17 significant digits: every double reads back to the same bits.
std::string number17(double v);

inline void print_number(std::ostream& out, double v) { out << number17(v); }

// Creates `folder` (and `subfolder` in it, when given) and their parents unless they exist.
void create_output_folder(const std::string& folder, const std::string& subfolder = std::string());

// The suffix of write_file_atomically's temporary files: this and the writer's process id.
const std::string TEMPORARY_SUFFIX = ".tmp.";

bool is_temporary_file_name(const std::string& name);

// Writes `path` through a temporary file in the same folder and a rename, so that a reader
// never sees a half-written file and a failure leaves nothing behind.
void write_file_atomically(const std::string& path, const std::function<void(std::ofstream&)>& write,
                                  bool binary = false);

// A script of the tool: $SIGMOID_NEIGHBORHOODS_SCRIPTS, else share/sigmoid-neighborhoods next to
// the executable once installed, else the source tree.
std::string find_tool_script(const std::string& name);

std::string python_interpreter();

// Runs the plotting script `name` of the tool with `arguments` (no shell); true when it succeeds.
bool run_python_script(const std::string& name, const std::vector<std::string>& arguments);

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
