// escaped_name: a file or clip name of any bytes as the UTF-8 text a motion store keeps and the
// tool reports (a byte of no UTF-8 sequence as \xHH, a backslash doubled), and unescaped_name,
// which gives the bytes back.
#include <deformseg/store/store_record.h>

#include <cstdio>
#include <initializer_list>
#include <string>

int main() {
  namespace store = deformseg::store;
  int failures = 0;
  // café.glb in Latin-1 (é is the byte E9), café.glb in UTF-8 (é is C3 A9), a backslash.
  for (const std::string& name : {std::string("caf\xE9.glb"), std::string("caf\xC3\xA9.glb"), std::string("a\\b")}) {
    const std::string text = store::escaped_name(name);
    const bool back = store::unescaped_name(text) == name;
    std::printf("%-12s UTF-8: %-3s kept as %-14s read back: %s\n", store::is_utf8(name) ? "(UTF-8)" : "(Latin-1)",
                store::is_utf8(text) ? "yes" : "no", text.c_str(), back ? "the same bytes" : "other bytes");
    failures += back && store::is_utf8(text) ? 0 : 1;
  }
  return failures;
}
