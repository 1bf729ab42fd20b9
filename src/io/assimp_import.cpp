// Assimp's import through its C API, the library opened with dlopen on the first import
// (io/internal/assimp_import.h). Assimp's library, with the zlib, minizip and standard library code
// it brings, costs every start of a program that links it the loader's time; a program that reads
// no FBX, Collada or BVH file should not pay it. The C API's functions are a handful of plain
// symbols (the C++ API's are mangled, and change with the compiler), and `aiScene` is read through
// Assimp's headers as before, so the scene and what is made of it are the same to the bit.
#include <deformseg/io/internal/assimp_import.h>

#include <deformseg/exceptions.h>

#include <assimp/cimport.h>
#include <dlfcn.h>

#include <limits>
#include <mutex>
#include <string>

// The library's file name (its soname: the one a program linking it would load) and its Debian
// package, for the message when it cannot be loaded: set by CMakeLists.txt from Assimp's target.
// DEFORMSEG_ASSIMP_LINKED instead where Assimp has no soname to open (a static Assimp): linked.
#if !defined(DEFORMSEG_ASSIMP_SONAME) && !defined(DEFORMSEG_ASSIMP_LINKED)
#error "DEFORMSEG_ASSIMP_SONAME (Assimp's soname, e.g. libassimp.so.5) or DEFORMSEG_ASSIMP_LINKED must be defined"
#endif
#ifndef DEFORMSEG_ASSIMP_SONAME
#define DEFORMSEG_ASSIMP_SONAME "Assimp's library"
#endif
#ifndef DEFORMSEG_ASSIMP_PACKAGE
#define DEFORMSEG_ASSIMP_PACKAGE "libassimp"
#endif

namespace deformseg::io::internal::assimp {
namespace {

// The functions of Assimp's C API that the readers call, resolved from the library.
struct C_api {
  decltype(&aiCreatePropertyStore) create_store = nullptr;
  decltype(&aiReleasePropertyStore) release_store = nullptr;
  decltype(&aiSetImportPropertyInteger) set_integer = nullptr;
  decltype(&aiImportFileFromMemoryWithProperties) import = nullptr;
  decltype(&aiGetErrorString) error = nullptr;
  decltype(&aiReleaseImport) release = nullptr;
  std::string failure{};  // why the library or a function could not be had; empty when all were
};

// Resolves `name` in `library` into `function`; false (and `api.failure` says why) when absent.
template <typename Function>
bool resolve(void* library, const char* name, Function& function, C_api& api) {
  dlerror();  // a null symbol is an error only when dlerror says so
  void* symbol = dlsym(library, name);
  if (const char* error = dlerror(); error || !symbol) {
    api.failure = error ? error : std::string(name) + " is null";
    return false;
  }
  function = reinterpret_cast<Function>(symbol);
  return true;
}

// Opens the library and resolves the C API. The library stays loaded for the process: scenes it
// made may outlive any caller, and unloading it would run its static destructors mid-process.
C_api open_api() {
#ifdef DEFORMSEG_ASSIMP_LINKED
  return {.create_store = &aiCreatePropertyStore,
          .release_store = &aiReleasePropertyStore,
          .set_integer = &aiSetImportPropertyInteger,
          .import = &aiImportFileFromMemoryWithProperties,
          .error = &aiGetErrorString,
          .release = &aiReleaseImport};
#else
  C_api api;
  void* library = dlopen(DEFORMSEG_ASSIMP_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* error = dlerror();
    api.failure = error ? error : "dlopen failed";
    return api;
  }
  // && stops at the first missing function, whose name `failure` then holds.
  (void)(resolve(library, "aiCreatePropertyStore", api.create_store, api) &&
         resolve(library, "aiReleasePropertyStore", api.release_store, api) &&
         resolve(library, "aiSetImportPropertyInteger", api.set_integer, api) &&
         resolve(library, "aiImportFileFromMemoryWithProperties", api.import, api) &&
         resolve(library, "aiGetErrorString", api.error, api) && resolve(library, "aiReleaseImport", api.release, api));
  return api;
#endif
}

// The C API, opened on the first call (a function-local static: once, thread-safely); throws
// invalid_input saying what to install when it could not be opened.
const C_api& api() {
  static const C_api opened = open_api();
  if (!opened.failure.empty())
    throw invalid_input("reading it needs Assimp (" DEFORMSEG_ASSIMP_SONAME ", Debian package " DEFORMSEG_ASSIMP_PACKAGE
                        "), which could not be loaded: " +
                        opened.failure);
  return opened;
}

// Assimp's C API keeps the message of the last failed import in one global string, which a
// failing import writes: imports run one at a time, and the message is read before the next.
std::mutex import_mutex;

// The property store of one import, released by its destructor.
struct Property_store {
  const C_api& api;
  aiPropertyStore* store;
  explicit Property_store(const C_api& c) : api(c), store(c.create_store()) {}
  ~Property_store() { api.release_store(store); }
  Property_store(const Property_store&) = delete;
  Property_store& operator=(const Property_store&) = delete;
};

}  // namespace

void Scene_release::operator()(const aiScene* scene) const noexcept {
  // A scene exists only if the library was opened, so api() does not throw here.
  if (scene) api().release(scene);
}

Import_result import_from_memory(std::string_view bytes, unsigned steps, const char* hint,
                                 std::initializer_list<Import_property> properties) {
  const C_api& c = api();
  if (bytes.size() > std::numeric_limits<unsigned>::max())
    throw invalid_input("the file is larger than Assimp reads (4 GiB - 1 bytes)");
  // Assimp::Importer's message for no bytes, which the C API returns without setting.
  if (bytes.empty()) return {.scene = nullptr, .error = "Invalid parameters passed to ReadFileFromMemory()"};
  Property_store store(c);
  for (const Import_property& property : properties) c.set_integer(store.store, property.name, property.value);
  const std::lock_guard<std::mutex> lock(import_mutex);
  Import_result result;
  result.scene.reset(c.import(bytes.data(), unsigned(bytes.size()), steps, hint, store.store));
  if (!result.scene) result.error = c.error();
  return result;
}

}  // namespace deformseg::io::internal::assimp
