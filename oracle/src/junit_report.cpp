#include "junit_report.h"

#include <tinyxml2.h>

#include <cstdio>
#include <map>
#include <vector>

#include "core/text.h"
#include "diagnosis.h"
#include "printable_text.h"

namespace fosssim {

namespace {

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", seconds);
  return text;
}

bool is_error(const SceneResult& r) {
  return r.verdict == Verdict::kSceneError || r.verdict == Verdict::kInterrupted;
}

std::string summary_line(const SceneResult& r) {
  std::string line = std::string(verdict_label(r.verdict));
  if (!r.integrator.empty())
    line += ": " + r.integrator + ", " + std::to_string(r.steps) + " steps";
  if (r.residuals) {
    line += "; maximum position residual " + to_text(r.residuals->max_position) +
            ", maximum velocity residual " + to_text(r.residuals->max_velocity);
  }
  return line + "\n";
}

/// Failures, errors and time of a set of scenes, for a <testsuites> or <testsuite> element.
struct JunitCounts {
  int failures = 0;
  int errors = 0;
  double seconds = 0.0;
};

JunitCounts junit_counts(const std::vector<const SceneResult*>& results) {
  JunitCounts t;
  for (const SceneResult* r : results) {
    if (!r->passed()) (is_error(*r) ? t.errors : t.failures) += 1;
    t.seconds += r->seconds();
  }
  return t;
}

/// The scenes of one report group, in run order.
struct Suite {
  std::string name;
  bool extra_credit = false;
  std::vector<const SceneResult*> results;
};

std::vector<Suite> group_suites(const std::vector<SceneResult>& results) {
  std::vector<Suite> suites;
  std::map<std::pair<bool, std::string>, std::size_t> index;
  for (const SceneResult& r : results) {
    const auto key = std::make_pair(r.extra_credit, r.suite());
    auto [it, inserted] = index.emplace(key, suites.size());
    if (inserted) suites.push_back({key.second, key.first, {}});
    suites[it->second].results.push_back(&r);
  }
  return suites;
}

void print_testcase(tinyxml2::XMLPrinter& xml, const SceneResult& r) {
  const std::string suite = r.suite();
  std::string classname = suite;
  for (char& c : classname) {
    if (c == '/') c = '.';
  }
  xml.OpenElement("testcase");
  xml.PushAttribute("name",
                    printable_text(r.name.substr(suite == "." ? 0 : suite.size() + 1)).c_str());
  xml.PushAttribute("classname", printable_text(classname).c_str());
  xml.PushAttribute("time", seconds_text(r.seconds()).c_str());
  if (!r.passed()) {
    xml.OpenElement(is_error(r) ? "error" : "failure");
    xml.PushAttribute("message", printable_text(first_line(r.reason)).c_str());
    xml.PushAttribute("type", verdict_id(r.verdict));
    xml.PushText(printable_text(diagnosis_text(r)).c_str());
    xml.CloseElement();
  }
  xml.OpenElement("system-out");
  xml.PushText(summary_line(r).c_str());
  xml.CloseElement();
  if (!r.stderr_tail.empty()) {
    xml.OpenElement("system-err");
    xml.PushText(printable_text(r.stderr_tail).c_str());
    xml.CloseElement();
  }
  xml.CloseElement();
}

}  // namespace

std::string junit_xml(const GradingRun& run) {
  tinyxml2::XMLPrinter xml(nullptr, false);
  xml.PushDeclaration("xml version=\"1.0\" encoding=\"UTF-8\"");
  std::vector<const SceneResult*> all;
  for (const SceneResult& r : run.results) all.push_back(&r);
  const JunitCounts total = junit_counts(all);
  xml.OpenElement("testsuites");
  xml.PushAttribute("name", "fosssim-oracle");
  xml.PushAttribute("tests", static_cast<int>(run.results.size()));
  xml.PushAttribute("failures", total.failures);
  xml.PushAttribute("errors", total.errors);
  xml.PushAttribute("time", seconds_text(total.seconds).c_str());
  for (const Suite& suite : group_suites(run.results)) {
    const JunitCounts suite_counts = junit_counts(suite.results);
    xml.OpenElement("testsuite");
    xml.PushAttribute("name", printable_text(suite.name).c_str());
    xml.PushAttribute("tests", static_cast<int>(suite.results.size()));
    xml.PushAttribute("failures", suite_counts.failures);
    xml.PushAttribute("errors", suite_counts.errors);
    xml.PushAttribute("skipped", 0);
    xml.PushAttribute("time", seconds_text(suite_counts.seconds).c_str());
    xml.OpenElement("properties");
    xml.OpenElement("property");
    xml.PushAttribute("name", "candidate");
    xml.PushAttribute("value", printable_text(run.candidate).c_str());
    xml.CloseElement();
    xml.OpenElement("property");
    xml.PushAttribute("name", "kind");
    xml.PushAttribute("value", suite.extra_credit ? "extra-credit" : "regular");
    xml.CloseElement();
    if (!run.sandboxed) {
      xml.OpenElement("property");
      xml.PushAttribute("name", "sandbox");
      xml.PushAttribute("value", "none (--no-sandbox)");
      xml.CloseElement();
    }
    xml.CloseElement();
    for (const SceneResult* r : suite.results) print_testcase(xml, *r);
    xml.CloseElement();
  }
  xml.CloseElement();
  return xml.CStr();
}

}  // namespace fosssim
