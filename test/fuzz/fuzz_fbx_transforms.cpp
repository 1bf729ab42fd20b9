// libFuzzer harness of the binary FBX walker that reads FBX nodes' local transforms
// (io/internal/fbx_local_transforms.h): the input as a binary FBX file, its record tree walked,
// its Models' transforms made, and its Models paired with a node tree of the root's Models, as
// Assimp would read them. Assimp's own FBX parsing is not fuzzed here (see fuzz_fbx_collada.cpp).
#include "fuzz_support.h"

#include <deformseg/io/internal/fbx_local_transforms.h>

#include <assimp/scene.h>

#include <memory>
#include <string>
#include <vector>

namespace fbx_transforms_harness {

namespace fbx = deformseg::io::internal::assimp::fbx;

// A scene whose root has a child node per Model connected to the file's root, named as it.
std::unique_ptr<aiScene> scene_of(const fbx::Model_tree& tree) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("RootNode");
  const auto roots = tree.children.find(0);
  if (roots == tree.children.end()) return scene;
  std::vector<aiNode*> children;
  for (const std::int64_t id : roots->second) children.push_back(new aiNode(tree.models.at(id).name));
  if (!children.empty()) scene->mRootNode->addChildren(unsigned(children.size()), children.data());
  return scene;
}

}  // namespace fbx_transforms_harness

DEFORMSEG_FUZZ_READER(fbx_transforms) {
  namespace fbx = deformseg::io::internal::assimp::fbx;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const fbx::Model_tree tree = fbx::model_tree(fbx::Binary_file(bytes));
  for (const auto& [id, model] : tree.models) static_cast<void>(fbx::simple_transform(model.properties));
  static_cast<void>(fbx::local_transforms(bytes, *fbx_transforms_harness::scene_of(tree)));
  return 0;
}
