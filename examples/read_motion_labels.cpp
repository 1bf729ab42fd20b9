// read_motion_labels: the labels of a retrieval evaluation, from a CSV file a spreadsheet can
// write: which file and clip each animation is, its motion ("-" for a distractor), body and rig.
#include <deformseg/evaluation/motion_labels.h>

#include <cstdio>
#include <fstream>
#include <vector>

int main() {
  using namespace deformseg;
  std::ofstream("labels.csv") << "file,clip,motion,rig,body\n"
                                 "# the KayKit knight and a fox\n"
                                 "Knight.glb,Walking_A,walk,kaykit,knight\n"
                                 "Knight.glb,Cheer,-,kaykit,knight\n"
                                 "\"Fox, from glTF samples.glb\",Walk,walk,,fox\n";
  const std::vector<evaluation::Labelled_clip> rows = evaluation::read_motion_labels("labels.csv");
  for (const evaluation::Labelled_clip& row : rows)
    std::printf("%-30s clip %-10s motion %-5s body %-7s rig '%s'\n", row.file.string().c_str(), row.item.clip.c_str(),
                row.item.motion.c_str(), row.item.body.c_str(), row.item.rig.c_str());
  return rows.size() == 3 && rows[1].item.motion == evaluation::distractor_label && rows[2].item.rig.empty() ? 0 : 1;
}
