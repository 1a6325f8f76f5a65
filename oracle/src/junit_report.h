#pragma once
// JUnit XML for CI systems (GitLab, Jenkins, GitHub test reporters): one <testsuite> per scene
// folder, one <testcase> per scene.

#include <string>

#include "grading_run.h"

namespace fosssim {

/// The JUnit XML document of a run. A scene the candidate fails is a <failure> whose type is
/// the verdict identifier ("failed", "crashed", "timeout", ...) and whose message is the reason;
/// its text is the diagnosis. A scene file that cannot be loaded (a problem of the suite, not of
/// the candidate) is an <error>. Extra-credit folders are their own suites, marked with the
/// property kind=extra-credit. Times are seconds: candidate run plus grading.
std::string junit_xml(const GradingRun& run);

}  // namespace fosssim
