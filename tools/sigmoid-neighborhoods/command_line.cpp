// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every command shares (command_line.h), compiled once for the tool.

#include "command_line.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sigmoid_tool {

Arguments::Arguments(int argc, char** argv, int first, const std::vector<std::string>& valued,
                     const std::vector<std::string>& flags, const std::vector<std::string>& triples)
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

double Arguments::get_double(const std::string& name, double fallback) const
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

std::vector<double> Arguments::get_doubles(const std::string& name) const
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

unsigned int Arguments::get_unsigned(const std::string& name, unsigned int fallback) const
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

bool Arguments::is_number(const std::string& s)
{
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return *end == '\0';
}

bool print_help(const Arguments& args, const char* usage)
{
  if(!args.has("-h") && !args.has("--help"))
    return false;
  std::cout << usage;
  return true;
}

std::pair<std::string, std::string> one_input_and_output(const Arguments& args, const std::string& command,
                                                                const std::string& output_description)
{
  if(args.positional().size() != 1)
    throw Usage_error(command + " needs exactly one INPUT");
  const std::string output = args.output();
  if(output.empty())
    throw Usage_error(command + " needs -o " + output_description);
  return {args.positional()[0], output};
}

double read_angle_tolerance(const Arguments& args, double fallback)
{
  const double tolerance = args.get_double("--angle-tolerance", fallback);
  if(!(tolerance >= 0. && tolerance < CGAL_PI))
    throw Usage_error("--angle-tolerance must be in [0, pi)");
  return tolerance;
}

std::vector<double> read_angle_list(const Arguments& args, const std::string& name,
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
      const std::vector<double> grid = CGAL::Sigmoid_neighborhoods::defaults::angle_grid();
      v = step == std::floor(step) ? grid[std::size_t(step)] : v * CGAL_PI / 180.;
    }
    angles.push_back(v);
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  return angles;
}

std::vector<std::string> split(const std::string& text, char separator)
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

std::vector<std::uint32_t> point_indices(std::size_t n)
{
  std::vector<std::uint32_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::uint32_t(0));
  return indices;
}

std::string number17(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

void create_output_folder(const std::string& folder, const std::string& subfolder)
{
  std::error_code ec;
  fs::create_directories(fs::path(folder) / subfolder, ec);
  if(ec)
    throw Usage_error("cannot create " + folder + ": " + ec.message());
}

bool is_temporary_file_name(const std::string& name)
{
  const std::size_t at = name.rfind(TEMPORARY_SUFFIX);
  const std::size_t id = at + TEMPORARY_SUFFIX.size();
  return at != std::string::npos && id < name.size() && name.find_first_not_of("0123456789", id) == std::string::npos;
}

void write_file_atomically(const std::string& path, const std::function<void(std::ofstream&)>& write,
                                  bool binary)
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

std::string find_tool_script(const std::string& name)
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

std::string python_interpreter()
{
  // Debian's interpreter has matplotlib; a python3 earlier on PATH may not.
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

bool run_python_script(const std::string& name, const std::vector<std::string>& arguments)
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
unsigned int resolved_threads(unsigned int requested)
{
#ifdef _OPENMP
  return requested != 0 ? requested : unsigned((std::max)(1, omp_get_max_threads()));
#else
  return requested != 0 ? requested : 1u;
#endif
}

} // namespace sigmoid_tool
