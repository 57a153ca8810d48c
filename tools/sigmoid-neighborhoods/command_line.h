// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small helpers shared by the subcommands: option parsing, exit codes, atomic output files.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
#define SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace sigmoid_tool {

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

// `--name value` options and positional arguments; every option must be known.
class Arguments
{
public:
  Arguments(int argc, char** argv, int first, const std::vector<std::string>& valued,
            const std::vector<std::string>& flags = {})
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
        if(contains(flags, arg))
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

  unsigned int get_unsigned(const std::string& name, unsigned int fallback) const
  {
    if(!has(name))
      return fallback;
    const std::string text = get(name);
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if(text.empty() || *end != '\0' || errno != 0 || v < 0 || v > 1000000)
      throw Usage_error("option " + name + " needs a non-negative integer, got '" + text + "'");
    return static_cast<unsigned int>(v);
  }

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

// The suffix of write_file_atomically's temporary files: ".tmp." and the writer's process id.
inline bool is_temporary_file_name(const std::string& name)
{
  const std::size_t at = name.rfind(".tmp.");
  return at != std::string::npos && at + 5 < name.size() &&
         name.find_first_not_of("0123456789", at + 5) == std::string::npos;
}

// Writes `path` through a temporary file in the same folder and a rename, so that a reader
// never sees a half-written file and a failure leaves nothing behind.
inline void write_file_atomically(const std::string& path, const std::function<void(std::ofstream&)>& write,
                                  bool binary = false)
{
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
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

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_COMMAND_LINE_H
