// core/shared_library: opening an optional library, filling a function table from it, and the
// "unavailable" errors that name the file, the loader's reason and the package to install.
// libc.so.6 stands for an optional library: it is always there, and strlen and atoi are C
// functions with one declaration each.

#include "core/shared_library.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "support/thrown.h"

namespace fosssim {
namespace {

constexpr const char* kNoSuchLibrary = "libFOSSSim-no-such-library.so";

#define FOSSSIM_TEST_LIBC_FUNCTIONS(X) X(strlen) X(atoi)

/// A table as the optional libraries' are declared, from the first file of two that loads.
struct LibcTable {
  SharedLibrary library =
      SharedLibrary::open({kNoSuchLibrary, "libc.so.6"}, "tests need libc", "libc6");
  FOSSSIM_TEST_LIBC_FUNCTIONS(FOSSSIM_LIBRARY_FUNCTION)
};

TEST(SharedLibrary, OpensTheFirstFileThatLoadsAndFillsATableOfItsFunctions) {
  const LibcTable table;
  ASSERT_NE(table.strlen, nullptr);
  ASSERT_NE(table.atoi, nullptr);
  EXPECT_EQ(table.strlen("four"), 4u);
  EXPECT_EQ(table.atoi("-273"), -273);
  EXPECT_EQ(table.library.find("fosssim_no_such_function"), nullptr);
}

TEST(SharedLibrary, ALibraryThatDoesNotLoadIsUnavailableWithEveryFileReasonAndThePackage) {
  const std::string second = std::string(kNoSuchLibrary) + ".2";
  const Error error = thrown_by([&] {
    SharedLibrary::open({kNoSuchLibrary, second}, "tests need Foo", "libfoo1",
                        SharedLibrary::Scope::kGlobal);
  });
  EXPECT_EQ(error.kind(), ErrorKind::kUnavailable);
  const std::string message = error.what();
  // The loader's reason names the file and says why: "<file>: cannot open shared object file".
  const std::string first_reason =
      std::string("cannot load ") + kNoSuchLibrary + ": " + kNoSuchLibrary + ": ";
  EXPECT_EQ(message.rfind("tests need Foo: " + first_reason, 0), 0u) << message;
  EXPECT_NE(message.find("; cannot load " + second + ": " + second + ": "), std::string::npos)
      << message;
  const std::string end = " (install the libfoo1 package)";
  ASSERT_GT(message.size(), end.size());
  EXPECT_EQ(message.substr(message.size() - end.size()), end) << message;
}

TEST(SharedLibrary, AMissingFunctionIsUnavailableNamingTheFileAndTheFunction) {
  const SharedLibrary library = SharedLibrary::open({"libc.so.6"}, "tests need libc", "libc6");
  const Error error = thrown_by([&] { library.symbol<int (*)()>("fosssim_no_such_function"); });
  EXPECT_EQ(error.kind(), ErrorKind::kUnavailable);
  EXPECT_EQ(std::string(error.what())
                .rfind("tests need libc: libc.so.6 lacks fosssim_no_such_function (", 0),
            0u)
      << error.what();
}

}  // namespace
}  // namespace fosssim
