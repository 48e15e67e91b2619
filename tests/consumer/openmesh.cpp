// SPDX-License-Identifier: MIT
// The installed opt-in header <seamless/mesh/openmesh.h>: tessellates a model,
// converts the mesh to OpenMesh and back, and prints "same" when every
// position and triangle came back unchanged.
#include <seamless/mesh/openmesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const seamless::TriangleMesh mesh =
        seamless::tessellate(seamless::load_model(argv[1]), {}).mesh;
    const seamless::TriangleMesh back = seamless::from_openmesh(seamless::to_openmesh(mesh));
    const bool same = back.positions == mesh.positions && back.triangles == mesh.triangles;
    std::cout << (same ? "same" : "changed") << "\n";
    return 0;
}
