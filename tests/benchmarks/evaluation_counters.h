// The benchmark counters of one design evaluation: every entry of its time split
// (ergo/design/evaluation_timing.h), the scene's sizes and whether it succeeded. Shared by
// design_benchmark and scaling_benchmark.
#pragma once

#include <benchmark/benchmark.h>

#include "ergo/design/design_problem.h"
#include "problems/scenario.h"

namespace ergo {

inline void ReportEvaluationCounters(benchmark::State& state, const Scenario& scenario,
                                     const DesignEvaluation& e) {
  ForEachTimingEntry(
      e.timing, [&](const char* name, double seconds) { state.counters[name] = seconds; },
      [&](const char* name, long count) { state.counters[name] = static_cast<double>(count); });
  state.counters["body_vertices"] = static_cast<double>(scenario.body->rest().vertices.rows());
  state.counters["support_vertices"] = static_cast<double>(scenario.support.vertices.rows());
  state.counters["ok"] = e.ok ? 1 : 0;
}

}  // namespace ergo
