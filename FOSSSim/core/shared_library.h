#pragma once
// Optional libraries, opened with dlopen when first needed rather than linked, so that a run that
// never needs one never maps it (docs/architecture.md, "Libraries loaded on demand"). The code
// that calls one declares a table: the opened library first, then the functions it calls, each
// declared by FOSSSIM_LIBRARY_FUNCTION from an X-macro list, typed by the library's own header
// (decltype of the declaration, which references no symbol: nothing links) and found as the
// table is constructed. A function-local static table loads once; a failed load throws and is
// tried again on the next call. viewer/glut_library.h and .cpp are the whole of it for GLUT.
// Not in the WebAssembly build.

#include <string>
#include <utility>
#include <vector>

namespace fosssim {

/// One opened library, never closed (its functions may be called until the process ends).
class SharedLibrary {
 public:
  /// Where the library's symbols go: kLocal (RTLD_LOCAL) keeps them to it, the rule; kGlobal
  /// (RTLD_GLOBAL) adds them to the global scope, for a library whose plug-ins, which it opens
  /// itself, take its symbols from there (OpenMPI's components).
  enum class Scope { kLocal, kGlobal };

  /// Opens the first of `files` (sonames or paths, searched as dlopen searches) that loads, with
  /// every symbol bound now (RTLD_NOW). When none does, throws Error (kUnavailable: exit 2)
  /// "<context>: cannot load <file>: <the loader's reason>[; …] (install the <package> package)",
  /// where `context` says who needs it ("pictures need Cairo") and `package` is Debian's.
  static SharedLibrary open(const std::vector<std::string>& files, std::string context,
                            const std::string& package, Scope scope = Scope::kLocal);

  /// The address of `name` in the library or those it depends on (dlsym on its handle, never
  /// the global scope: the program's own definitions of a name are not found), or nullptr.
  void* find(const char* name) const;
  /// `name` as a Pointer (a function or object pointer type), found as by find. Throws Error
  /// (kUnavailable) "<context>: <file> lacks <name> (…)" when it is not there.
  template <class Pointer>
  Pointer symbol(const char* name) const {
    return reinterpret_cast<Pointer>(require(name));
  }

 private:
  SharedLibrary(void* handle, std::string file, std::string context)
      : handle_(handle), file_(std::move(file)), context_(std::move(context)) {}
  void* require(const char* name) const;

  void* handle_;
  std::string file_;
  std::string context_;
};

}  // namespace fosssim

/// A member of a function table: a pointer named and typed as the header's function `name`,
/// found in the table's member `library` (declared before it).
#define FOSSSIM_LIBRARY_FUNCTION(name) \
  decltype(&::name) name = library.symbol<decltype(&::name)>(#name);
