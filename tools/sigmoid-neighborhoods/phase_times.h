// Copyright (c) 2026 Sigmoid_neighborhoods contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The wall time of a command's phases, in the order they ran: the end of its summary line and the
// "phases" of a tile's .tile.json, from which benchmark/phase_fractions.py computes the sequential
// fraction of a run.

#ifndef SIGMOID_NEIGHBORHOODS_TOOL_PHASE_TIMES_H
#define SIGMOID_NEIGHBORHOODS_TOOL_PHASE_TIMES_H

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace sigmoid_tool {

class Phase_times
{
public:
  Phase_times() : m_start(clock::now()), m_last(m_start) {}

  // Ends the phase `name`: the time since the previous one ended (or since construction).
  void end(const std::string& name) { add(name, seconds_since_last()); }

  // Ends the reading: the reader's time split into the steps of its normal estimation and the rest,
  // the reading itself (files, parsing, checks, merging, a tile's halo). A template on the package's
  // Oriented_point_set, so that commands that read none (retile) do not compile CGAL's kernel.
  template <typename Oriented_point_set>
  void end_reading(const Oriented_point_set& model)
  {
    const auto& s = model.seconds;
    const double total = seconds_since_last();
    add("reading", total - s.neighbor_rows - s.normal_estimation - s.orientation);
    add("neighbor rows", s.neighbor_rows);
    add("normal estimation", s.normal_estimation);
    add("orientation", s.orientation);
  }

  // Adds `seconds` to the phase `name` (a phase timed inside another step; zero phases are not listed).
  void add(const std::string& name, double seconds)
  {
    if(seconds <= 0.)
      return;
    for(auto& p : m_phases)
      if(p.first == name)
      {
        p.second += seconds;
        return;
      }
    m_phases.emplace_back(name, seconds);
  }

  // Moves `seconds` from the phase `from` to `to` (a step timed inside another phase).
  void move(const std::string& from, const std::string& to, double seconds)
  {
    for(auto& p : m_phases)
      if(p.first == from)
        p.second -= seconds;
    add(to, seconds);
  }

  double total() const { return std::chrono::duration<double>(clock::now() - m_start).count(); }

  // "reading 1.20 s, orientation 0.31 s, search 5.02 s, writing 0.80 s"
  std::string text() const
  {
    std::string s;
    for(const auto& p : m_phases)
    {
      char seconds[32];
      std::snprintf(seconds, sizeof(seconds), "%.2f", p.second);
      s += (s.empty() ? "" : ", ") + p.first + ' ' + seconds + " s";
    }
    return s;
  }

  // {"reading": 1.2, ...} in seconds, in the order the phases ran
  nlohmann::ordered_json json() const
  {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for(const auto& p : m_phases)
      j[p.first] = p.second;
    return j;
  }

private:
  typedef std::chrono::steady_clock clock;

  double seconds_since_last()
  {
    const auto now = clock::now();
    const double seconds = std::chrono::duration<double>(now - m_last).count();
    m_last = now;
    return seconds;
  }

  clock::time_point m_start, m_last;
  std::vector<std::pair<std::string, double>> m_phases;
};

} // namespace sigmoid_tool

#endif // SIGMOID_NEIGHBORHOODS_TOOL_PHASE_TIMES_H
