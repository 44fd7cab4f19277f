#pragma once
// A conformance run (suite.hpp) written for people and for CI: the terminal report (each failing
// vector with its first bad pixels explained), one JSON document (every bad pixel, the explained
// ones with their histories), JUnit XML (one test case per vector), and a self-contained HTML
// page (error masks coloured by stage, the histories, the named reading).

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "recode/conformance/suite.hpp"

namespace recode::conformance {

// One vector's lines of the terminal report: its status line, then for a failure the stage,
// the section, what the APIs require and `pixels` bad pixels explained.
void printVector(std::ostream& out, const VectorReport& v, std::size_t pixels);
// The status line alone (what a run prints as each vector finishes: the stages are final only
// once the whole run has named the reading a back end behaves like).
void printVectorLine(std::ostream& out, const VectorReport& v);
// Whether printVector says more than the status line.
[[nodiscard]] bool hasDetails(const VectorReport& v);
// The closing lines: counts, the named reading or the stages, the error.
void printSummary(std::ostream& out, const SuiteReport& report);

// `fields`: top-level string members to add, e.g. {"device", "cpu"} or {"exec", "..."}.
[[nodiscard]] std::string toJson(
    const SuiteReport& report, const std::vector<std::pair<std::string, std::string>>& fields = {});
[[nodiscard]] std::string toJunit(const SuiteReport& report);
[[nodiscard]] std::string toHtml(const SuiteReport& report);

// "behaves like: <what> (<name>)" for the named readings, or the stages at which the failing
// vectors first depart; empty when nothing failed.
[[nodiscard]] std::string verdict(const SuiteReport& report);

}  // namespace recode::conformance
