// Scenes built in code for the stability tests: small constructors for the scene model's parts and
// generated meshes (closed and open), so every test states its whole scene where it is used.
#pragma once

#include <glm/glm.hpp>

#include "scene.h"
#include "scene_builder.h"

namespace vkrt::stability {

// The common constructors (tests/common/scene_builder.h), and a camera aimed at a point.
using test::areaLight;
using test::box;
using test::pointLight;
using test::sphere;
using test::triangle;
inline Camera orthographic(glm::vec3 position, glm::vec3 gaze, float planeWidth) {
    return test::orthographicCamera(position, gaze, planeWidth);
}
Camera perspective(glm::vec3 position, glm::vec3 lookAt, float focalLength = 1.0f, float planeWidth = 1.0f);

Shader lambertian(glm::vec3 diffuse);
Shader blinnPhong(glm::vec3 diffuse, glm::vec3 specular, float phongExp);
Shader mirror(float roughness = 0.0f);
Shader glossy(glm::vec3 diffuse, float mirrorCoef, float roughness);  // BlinnPhongMirrored
Shader dielectric(float eta, glm::vec3 attenuation = glm::vec3(1.0f));

// Index of the added element.
inline int add(Scene& scene, const Shader& shader) { return test::addShader(scene, shader); }
using test::addMesh;
// A mesh placed by a prototype + instance; returns the instance index.
int addInstancedMesh(Scene& scene, int mesh, int shader, const glm::mat4& objectToWorld);
// A mesh as a plain world-space shape.
void addLooseMesh(Scene& scene, int mesh, int shader);

// A closed "cube sphere" of radius r around the origin: each cube face is an n x n grid projected
// onto the sphere, edge and corner vertices shared between faces (so the mesh is closed and every
// edge has exactly two triangles). Vertex k sits at r * normalize(lattice point k), the lattice
// points being integer coordinates in [-n, n] with step 2; latticePoints() returns them so tests can
// aim rays at vertices exactly.
Mesh cubeSphere(int n, float r);
std::vector<glm::ivec3> cubeSphereLattice(int n);

// A closed torus in the xz-plane around the origin (ring radius R, tube radius r).
Mesh torus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments);

// Per-vertex normals from the faces (the loader's rule for OBJ files without vn).
void generateNormals(Mesh& mesh);

}  // namespace vkrt::stability
