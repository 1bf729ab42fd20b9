// Every module's umbrella header, compiled together: each is self-contained, and the modules'
// names do not collide when a program includes them all.
#include <deformseg/alignment.h>
#include <deformseg/clustering.h>
#include <deformseg/color.h>
#include <deformseg/evaluation.h>
#include <deformseg/ged.h>
#include <deformseg/io.h>
#include <deformseg/mesh.h>
#include <deformseg/search.h>
#include <deformseg/signatures.h>
#include <deformseg/similarity.h>
#include <deformseg/spatiotemporal.h>
#include <deformseg/store.h>
#include <deformseg/strain.h>
#include <deformseg/temporal.h>

namespace deformseg {
using namespace mesh;
using namespace strain;
using namespace signatures;
using namespace temporal;
using namespace spatiotemporal;
using namespace similarity;
using namespace search;
using namespace evaluation;
using namespace color;
using namespace io;
using namespace store;
// A name found in two modules would make this ambiguous.
static_assert(sizeof(mesh::Deforming_mesh<mesh::Surface_mesh>) > 0 && sizeof(strain::Strain_field<float>) > 0);
}  // namespace deformseg
