// libFuzzer harness of the FBX and Collada reader's own code: the adapter that writes an Assimp
// scene into glTF's structures (io/internal/assimp_*.h), then the glTF reader's sampling and
// welding of it. The input is decoded into an Assimp scene (a node tree, meshes with faces,
// bones, weights and morph targets, clips with node and morph channels), with indices, names,
// counts and values out of range on purpose; the same bytes, as the text of a Collada file, go
// through the checks of what Assimp drops (io/internal/collada_checks.h). Assimp's parsing itself
// is not fuzzed here: Debian's Assimp is not instrumented, so its faults would be neither seen nor
// ours to fix.
#include "fuzz_support.h"

#include <deformseg/io/fbx_collada.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/assimp_model.h>

#include <assimp/scene.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace fbx_collada_harness {

// The input read a byte at a time; zeros past its end.
class Bytes {
public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned next(unsigned below) { return below == 0 ? 0 : (at_ < size_ ? data_[at_++] : 0) % below; }
  // Small values in sixteenths, and a NaN for the byte 255.
  float value() {
    const unsigned byte = next(256);
    return byte == 255 ? std::numeric_limits<float>::quiet_NaN() : float(int(byte) - 128) / 16;
  }
  std::string name() { return "n" + std::to_string(next(10)); }

private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

// An array of `count` elements, null when empty: Assimp's destructors free only arrays of elements.
template <class T>
T* array(unsigned count) {
  return count == 0 ? nullptr : new T[count];
}

aiMatrix4x4 matrix(Bytes& in) {
  if (in.next(2) == 0) return aiMatrix4x4();
  aiMatrix4x4 m;
  for (ai_real* x = &m.a1; x != &m.a1 + 12; ++x) *x = in.value();
  return m;
}

aiMesh* mesh(Bytes& in, const aiNode& root) {
  aiMesh* m = new aiMesh;
  m->mName = root.mName;
  m->mNumVertices = in.next(8);
  m->mVertices = array<aiVector3D>(m->mNumVertices);
  for (unsigned v = 0; v < m->mNumVertices; ++v) m->mVertices[v] = aiVector3D(in.value(), in.value(), in.value());
  m->mNumFaces = in.next(6);
  m->mFaces = array<aiFace>(m->mNumFaces);
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    m->mFaces[f].mNumIndices = 1 + in.next(3);
    m->mFaces[f].mIndices = array<unsigned>(m->mFaces[f].mNumIndices);
    for (unsigned k = 0; k < m->mFaces[f].mNumIndices; ++k) m->mFaces[f].mIndices[k] = in.next(10);
  }
  m->mNumBones = in.next(3);
  m->mBones = array<aiBone*>(m->mNumBones);
  for (unsigned b = 0; b < m->mNumBones; ++b) {
    aiBone* bone = m->mBones[b] = new aiBone;
    bone->mName = in.name();
    bone->mOffsetMatrix = matrix(in);
    bone->mNumWeights = in.next(4);
    bone->mWeights = array<aiVertexWeight>(bone->mNumWeights);
    for (unsigned w = 0; w < bone->mNumWeights; ++w) bone->mWeights[w] = aiVertexWeight(in.next(10), in.value());
  }
  m->mNumAnimMeshes = in.next(2);
  m->mAnimMeshes = array<aiAnimMesh*>(m->mNumAnimMeshes);
  for (unsigned t = 0; t < m->mNumAnimMeshes; ++t) {
    aiAnimMesh* target = m->mAnimMeshes[t] = new aiAnimMesh;
    target->mNumVertices = in.next(2) == 0 ? m->mNumVertices : in.next(8);
    target->mVertices = array<aiVector3D>(target->mNumVertices);
    for (unsigned v = 0; v < target->mNumVertices; ++v) target->mVertices[v] = aiVector3D(in.value(), in.value(), in.value());
    target->mWeight = in.value();
  }
  return m;
}

template <class Key, class Make>
Key* keys(Bytes& in, unsigned& count, Make make) {
  count = in.next(4);
  Key* result = array<Key>(count);
  for (unsigned k = 0; k < count; ++k) result[k] = make(double(in.next(40)));
  return result;
}

aiAnimation* clip(Bytes& in) {
  aiAnimation* a = new aiAnimation;
  a->mName = in.name();
  a->mTicksPerSecond = in.next(30);
  a->mNumChannels = in.next(3);
  a->mChannels = array<aiNodeAnim*>(a->mNumChannels);
  for (unsigned c = 0; c < a->mNumChannels; ++c) {
    aiNodeAnim* channel = a->mChannels[c] = new aiNodeAnim;
    channel->mNodeName = in.name();
    const auto vector_key = [&](double t) { return aiVectorKey(t, aiVector3D(in.value(), in.value(), in.value())); };
    channel->mPositionKeys = keys<aiVectorKey>(in, channel->mNumPositionKeys, vector_key);
    channel->mRotationKeys = keys<aiQuatKey>(in, channel->mNumRotationKeys, [&](double t) {
      return aiQuatKey(t, aiQuaternion(in.value(), in.value(), in.value(), in.value()));
    });
    channel->mScalingKeys = keys<aiVectorKey>(in, channel->mNumScalingKeys, vector_key);
  }
  a->mNumMorphMeshChannels = in.next(2);
  a->mMorphMeshChannels = array<aiMeshMorphAnim*>(a->mNumMorphMeshChannels);
  for (unsigned c = 0; c < a->mNumMorphMeshChannels; ++c) {
    aiMeshMorphAnim* channel = a->mMorphMeshChannels[c] = new aiMeshMorphAnim;
    channel->mName = in.name();
    channel->mNumKeys = in.next(4);
    channel->mKeys = array<aiMeshMorphKey>(channel->mNumKeys);
    for (unsigned k = 0; k < channel->mNumKeys; ++k) {
      aiMeshMorphKey& key = channel->mKeys[k];
      key.mTime = in.next(40);
      key.mNumValuesAndWeights = in.next(3);
      key.mValues = array<unsigned>(key.mNumValuesAndWeights);
      key.mWeights = array<double>(key.mNumValuesAndWeights);
      for (unsigned i = 0; i < key.mNumValuesAndWeights; ++i) key.mValues[i] = in.next(3), key.mWeights[i] = in.value();
    }
  }
  return a;
}

// A scene of up to 8 nodes (each under an earlier one), 2 meshes and 1 clip.
aiScene* scene(Bytes& in) {
  aiScene* s = new aiScene;
  std::vector<aiNode*> nodes{new aiNode("n0")};
  s->mRootNode = nodes.front();
  for (unsigned n = 1, count = 1 + in.next(8); n < count; ++n) {
    aiNode* node = new aiNode(in.name());
    node->mParent = nodes[in.next(unsigned(nodes.size()))];
    node->mParent->addChildren(1, &node);
    nodes.push_back(node);
  }
  s->mNumMeshes = in.next(3);
  s->mMeshes = array<aiMesh*>(s->mNumMeshes);
  for (unsigned m = 0; m < s->mNumMeshes; ++m) s->mMeshes[m] = mesh(in, *s->mRootNode);
  for (aiNode* node : nodes) {
    node->mTransformation = matrix(in);
    node->mNumMeshes = in.next(3);
    node->mMeshes = array<unsigned>(node->mNumMeshes);
    for (unsigned k = 0; k < node->mNumMeshes; ++k) node->mMeshes[k] = in.next(4);
  }
  s->mNumAnimations = in.next(2);
  s->mAnimations = array<aiAnimation*>(s->mNumAnimations);
  for (unsigned a = 0; a < s->mNumAnimations; ++a) s->mAnimations[a] = clip(in);
  return s;
}


DEFORMSEG_FUZZ_READER(fbx_collada) {
  Bytes in(data, size);
  const std::unique_ptr<aiScene> built(scene(in));
  const std::filesystem::path name = "fuzz.fbx";
  deformseg::fuzz::expect_valid_outcome(name, [&](const std::filesystem::path& path) {
    tinygltf::Model model;
    try {
      deformseg::io::internal::collada::check_channel_targets(
          std::string_view(reinterpret_cast<const char*>(data), size));  // the same bytes as Collada text
      model = deformseg::io::internal::assimp::model_of(*built, 1);
    } catch (const deformseg::invalid_input& e) {
      throw e.located({.file = path.string()});
    }
    const deformseg::io::Gltf_file file(path, std::move(model));
    file.sample({.fps = 1, .threads = 1});
    file.repair();
  });
  return 0;
}

}  // namespace fbx_collada_harness
