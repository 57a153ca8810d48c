// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the subcommands share: option parsing and validation, exit codes, reading an input with a
// one-line error, output folders and atomic output files, numbers, and running the plotting scripts.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
#define SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H

#include "tool_paths.h"

#include <CGAL/Sigmoid_neighborhoods/IO/Input_error.h>
#include <CGAL/Sigmoid_neighborhoods/search_parameters.h>

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
            const std::vector<std::string>& flags = {}, const std::vector<std::string>& triples = {})
  {
    for(int i = first; i < argc; ++i)
    {
      std::string arg = argv[i];
      if(arg.size() > 1 && arg[0] == '-' && !is_number(arg))
      {
        std::string value;
        const std::size_t eq = arg.find('=');
        bool has_inline = false;
        if(eq != std::string::npos)
        {
          value = arg.substr(eq + 1);
          arg = arg.substr(0, eq);
          has_inline = true;
        }
        if(contains(triples, arg))
        {
          if(has_inline || i + 3 >= argc)
            throw Usage_error("option " + arg + " needs three values: " + arg + " X Y Z");
          m_options[arg] = std::string(argv[i + 1]) + ' ' + argv[i + 2] + ' ' + argv[i + 3];
          i += 3;
        }
        else if(contains(flags, arg))
        {
          if(has_inline)
            throw Usage_error("option " + arg + " takes no value");
          m_options[arg] = "1";
        }
        else if(contains(valued, arg))
        {
          if(!has_inline)
          {
            if(i + 1 >= argc)
              throw Usage_error("option " + arg + " needs a value");
            value = argv[++i];
          }
          m_options[arg] = value;
        }
        else
          throw Usage_error("unknown option " + arg);
      }
      else
        m_positional.push_back(arg);
    }
  }

  const std::vector<std::string>& positional() const { return m_positional; }
  const std::map<std::string, std::string>& options() const { return m_options; }
  bool has(const std::string& name) const { return m_options.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = std::string()) const
  {
    auto it = m_options.find(name);
    return it == m_options.end() ? fallback : it->second;
  }

  double get_double(const std::string& name, double fallback) const
  {
    if(!has(name))
      return fallback;
    const std::string text = get(name);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if(text.empty() || *end != '\0')
      throw Usage_error("option " + name + " needs a number, got '" + text + "'");
    return v;
  }

  // The three numbers of an option of `triples`.
  std::vector<double> get_doubles(const std::string& name) const
  {
    const std::string text = get(name);
    std::vector<double> values;
    const char* at = text.c_str();
    for(int i = 0; i < 3; ++i)
    {
      char* end = nullptr;
      const double v = std::strtod(at, &end);
      if(end == at || (*end != ' ' && *end != '\0') || !std::isfinite(v))
        throw Usage_error("option " + name + " needs three finite numbers, got '" + text + "'");
      values.push_back(v);
      at = end;
    }
    return values;
  }

  // Integer options are counts: sizes, iterations, threads; a larger one is a typing error.
  static constexpr long LARGEST_UNSIGNED_OPTION = 1000000;

  unsigned int get_unsigned(const std::string& name, unsigned int fallback) const
  {
    if(!has(name))
      return fallback;
    const std::string text = get(name);
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if(text.empty() || *end != '\0' || errno != 0 || v < 0 || v > LARGEST_UNSIGNED_OPTION)
      throw Usage_error("option " + name + " needs a non-negative integer, got '" + text + "'");
    return static_cast<unsigned int>(v);
  }

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
  static bool is_number(const std::string& s)
  {
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return *end == '\0';
  }

  std::map<std::string, std::string> m_options;
  std::vector<std::string> m_positional;
};

// Prints `usage` when -h or --help is given: the command then returns EXIT_OK.
inline bool print_help(const Arguments& args, const char* usage)
{
  if(!args.has("-h") && !args.has("--help"))
    return false;
  std::cout << usage;
  return true;
}

// The INPUT and the -o OUTPUT of a command on one model; `output_description` names what -o takes.
inline std::pair<std::string, std::string> one_input_and_output(const Arguments& args, const std::string& command,
                                                                const std::string& output_description)
{
  if(args.positional().size() != 1)
    throw Usage_error(command + " needs exactly one INPUT");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error(command + " needs -o " + output_description);
  return {args.positional()[0], output};
}

// --threads N: the threads of every parallel call (0: OpenMP's default).
inline unsigned int read_threads(const Arguments& args) { return args.get_unsigned("--threads", 0); }

// --angle-tolerance: a tolerance on angles in radians, in [0, pi).
inline double read_angle_tolerance(const Arguments& args, double fallback)
{
  const double tolerance = args.get_double("--angle-tolerance", fallback);
  if(!(tolerance >= 0. && tolerance < CGAL_PI))
    throw Usage_error("--angle-tolerance must be in [0, pi)");
  return tolerance;
}

// An option of comma-separated angles in [0, pi]: radians (`1.5`, `pi`) or degrees (`30deg`),
// sorted and deduplicated as the library does. Multiples of 30deg are the default grid's values
// bit for bit, so that `0,30deg,...,180deg` is the default grid.
inline std::vector<double> read_angle_list(const Arguments& args, const std::string& name,
                                           const std::vector<double>& fallback)
{
  if(!args.has(name))
    return fallback;
  const std::string text = args.get(name);
  if(text.empty())
    throw Usage_error("option " + name + " needs at least one angle");
  std::vector<double> angles;
  std::size_t start = 0;
  while(start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string word = text.substr(start, comma - start);
    start = comma + 1;
    const bool degrees = word.size() > 3 && word.compare(word.size() - 3, 3, "deg") == 0;
    const std::string number = degrees ? word.substr(0, word.size() - 3) : word;
    double v = 0.;
    char* end = nullptr;
    if(number == "pi")
      v = degrees ? std::nan("") : CGAL_PI;
    else
      v = std::strtod(number.c_str(), &end);
    if(number.empty() || (end != nullptr && *end != '\0') || std::isnan(v))
      throw Usage_error("option " + name + " needs comma-separated angles in radians or degrees (0,30deg,pi), got '" +
                        word + "'");
    if(!(v >= 0. && v <= (degrees ? 180. : CGAL_PI)))
      throw Usage_error("option " + name + ": " + word + " is not in [0, pi] (0 to 180deg)");
    if(degrees)
    {
      const double step = v / 30.;
      const std::vector<double> grid = CGAL::Sigmoid_neighborhoods::default_angle_grid();
      v = step == std::floor(step) ? grid[std::size_t(step)] : v * CGAL_PI / 180.;
    }
    angles.push_back(v);
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  return angles;
}

// The pieces of `text` between the separators `separator` (empty pieces included: "a,,b" has three).
inline std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> pieces;
  std::size_t start = 0;
  while(start <= text.size())
  {
    const std::size_t end = std::min(text.find(separator, start), text.size());
    pieces.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return pieces;
}

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
inline std::vector<std::uint32_t> point_indices(std::size_t n)
{
  std::vector<std::uint32_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::uint32_t(0));
  return indices;
}

// 17 significant digits: every double reads back to the same bits.
inline std::string number17(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

inline void print_number(std::ostream& out, double v) { out << number17(v); }

// Creates `folder` (and `subfolder` in it, when given) and their parents unless they exist.
inline void create_output_folder(const std::string& folder, const std::string& subfolder = std::string())
{
  std::error_code ec;
  fs::create_directories(fs::path(folder) / subfolder, ec);
  if(ec)
    throw Usage_error("cannot create " + folder + ": " + ec.message());
}

// The suffix of write_file_atomically's temporary files: this and the writer's process id.
const std::string TEMPORARY_SUFFIX = ".tmp.";

inline bool is_temporary_file_name(const std::string& name)
{
  const std::size_t at = name.rfind(TEMPORARY_SUFFIX);
  const std::size_t id = at + TEMPORARY_SUFFIX.size();
  return at != std::string::npos && id < name.size() && name.find_first_not_of("0123456789", id) == std::string::npos;
}

// Writes `path` through a temporary file in the same folder and a rename, so that a reader
// never sees a half-written file and a failure leaves nothing behind.
inline void write_file_atomically(const std::string& path, const std::function<void(std::ofstream&)>& write,
                                  bool binary = false)
{
  const std::string temporary = path + TEMPORARY_SUFFIX + std::to_string(::getpid());
  {
    std::ofstream out(temporary, binary ? std::ios::binary | std::ios::out : std::ios::out);
    if(!out)
      throw Usage_error("cannot write " + path + ": " + std::strerror(errno));
    errno = 0;
    try
    {
      write(out);
    }
    catch(...)
    {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    out.close(); // flushes what is left; a failure leaves failbit set
    if(out.fail())
    {
      // errno still holds the failed write's reason: ENOSPC, EDQUOT, EFBIG, EIO...
      const std::string reason = errno != 0 ? std::strerror(errno) : "write error";
      std::remove(temporary.c_str());
      throw Usage_error("cannot write " + path + ": " + reason);
    }
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw Usage_error("cannot write " + path + ": " + reason);
  }
}

// A script of the tool: $SIGMOID_NEIGHBORHOODS_SCRIPTS, else share/sigmoid-neighborhoods next to
// the executable once installed, else the source tree.
inline std::string find_tool_script(const std::string& name)
{
  std::vector<fs::path> candidates;
  if(const char* env = std::getenv("SIGMOID_NEIGHBORHOODS_SCRIPTS"))
    candidates.push_back(fs::path(env) / name);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if(!ec)
    candidates.push_back(exe.parent_path().parent_path() / "share" / "sigmoid-neighborhoods" / name);
  candidates.push_back(fs::path(tool_paths::script_dir()) / name);
  for(const auto& c : candidates)
    if(fs::exists(c, ec))
      return c.string();
  throw Usage_error("cannot find " + name + " (set SIGMOID_NEIGHBORHOODS_SCRIPTS)");
}

inline std::string python_interpreter()
{
  // Debian's interpreter has matplotlib; a python3 earlier on PATH may not.
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

// Runs the plotting script `name` of the tool with `arguments` (no shell); true when it succeeds.
inline bool run_python_script(const std::string& name, const std::vector<std::string>& arguments)
{
  std::vector<std::string> words = {python_interpreter(), find_tool_script(name)};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for(std::string& word : words)
    argv.push_back(&word[0]);
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  pid_t pid = 0;
  if(::posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    return false;
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0)
    if(errno != EINTR)
      return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
