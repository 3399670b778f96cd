// Unit tests of vtkLightShaftPass's geometry, on the CPU (no GL): polytope clipping, convex
// hulls and polygon clipping, the camera frame, the light's bounding pyramid and caster
// culling, the light camera, the lit volume, the slab footprints and their lattice.
//
// Usage: TestLightShaftGeometry

#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftModel.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << std::endl;
    ++Failures;
  }
}

double PolygonArea(const std::vector<glm::dvec2>& polygon)
{
  double area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i)
  {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
    area += a.x * b.y - a.y * b.x;
  }
  return 0.5 * area;
}

// Total area of the triangles AppendSlabTriangles wrote (x, y, slab, depth per vertex).
double TrianglesArea(const std::vector<float>& vertices)
{
  double area = 0.0;
  for (size_t v = 0; v + 11 < vertices.size(); v += 12)
  {
    const glm::dvec2 a(vertices[v], vertices[v + 1]);
    const glm::dvec2 b(vertices[v + 4], vertices[v + 5]);
    const glm::dvec2 c(vertices[v + 8], vertices[v + 9]);
    area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

void TestPolygons()
{
  // Hull of a square's corners and interior points: the corners, counter-clockwise.
  const std::vector<glm::dvec2> hull = vtkLightShaftGeometry::ConvexHull(
    { { 0, 0 }, { 1, 0 }, { 0.5, 0.5 }, { 1, 1 }, { 0.2, 0.7 }, { 0, 1 } });
  Check(hull.size() == 4, "hull of a square has 4 vertices");
  Check(std::abs(PolygonArea(hull) - 1.0) < 1e-12, "hull is counter-clockwise, area 1");

  // A square clipped to a triangle covering its lower-left half.
  const std::vector<glm::dvec2> clipped = vtkLightShaftGeometry::ClipToConvex(
    { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, { { -1, -1 }, { 4, -1 }, { -1, 4 } });
  Check(std::abs(PolygonArea(clipped) - 1.0) < 1e-12, "a square inside the window is kept");
  const std::vector<glm::dvec2> half = vtkLightShaftGeometry::ClipToConvex(
    { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, { { 0, 0 }, { 1, 0 }, { 0, 1 } });
  Check(std::abs(PolygonArea(half) - 0.5) < 1e-12, "square clipped to its lower triangle");

  // The unit cube clipped by x + y + z >= 1.5: every vertex on the kept side, a cap added.
  vtkLightShaftGeometry::ConvexPolytope cube;
  const glm::dvec3 c[8] = { { 0, 0, 0 },
    { 1, 0, 0 },
    { 1, 1, 0 },
    { 0, 1, 0 },
    { 0, 0, 1 },
    { 1, 0, 1 },
    { 1, 1, 1 },
    { 0, 1, 1 } };
  cube.Faces = { { c[0], c[3], c[2], c[1] },
    { c[4], c[5], c[6], c[7] },
    { c[0], c[1], c[5], c[4] },
    { c[2], c[3], c[7], c[6] },
    { c[1], c[2], c[6], c[5] },
    { c[0], c[4], c[7], c[3] } };
  cube.Clip(glm::dvec4(1.0, 1.0, 1.0, -1.5));
  bool inside = !cube.Empty();
  for (const auto& face : cube.Faces)
  {
    for (const glm::dvec3& p : face)
    {
      inside = inside && p.x + p.y + p.z >= 1.5 - 1e-12;
    }
  }
  Check(inside, "clipped cube lies on the kept side");
  Check(cube.Faces.size() == 7, "clipped cube: 6 faces cut or kept, and the cap");
  cube.Clip(glm::dvec4(1.0, 1.0, 1.0, -3.5));
  Check(cube.Empty(), "clipping everything away leaves nothing");
}

void TestCameraAndPyramid()
{
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
  const auto perspective = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 1.0, 100.0));
  Check(perspective.Perspective && std::abs(perspective.FarDepth - 100.0) < 1e-9,
    "perspective camera frame: far depth 100");
  const auto parallel = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::ortho(-4.0, 4.0, -3.0, 3.0, 1.0, 50.0));
  Check(!parallel.Perspective && std::abs(parallel.FarDepth - 50.0) < 1e-9,
    "parallel camera frame: far depth 50");
  Check(parallel.PixelFootprint(100).x == 0.0 &&
          std::abs(parallel.PixelFootprint(100).y - 0.08) < 1e-12,
    "parallel pixel footprint: 8 / 100 view units");

  vtkLightShaftGeometry::Pyramid pyramid;
  pyramid.Apex = glm::dvec3(0, 5, 0);
  pyramid.Axis = glm::dvec3(0, -1, 0);
  pyramid.U = glm::dvec3(1, 0, 0);
  pyramid.V = glm::dvec3(0, 0, 1);
  pyramid.Tangent = std::tan(glm::radians(20.0));
  const double below[6] = { -0.5, 0.5, 0, 1, -0.5, 0.5 };
  const double above[6] = { -0.5, 0.5, 6, 7, -0.5, 0.5 };
  const double beside[6] = { 4, 5, 0, 1, -0.5, 0.5 };
  const double around[6] = { -10, 10, -10, 10, -10, 10 };
  Check(pyramid.Reaches(below), "a box under the light reaches into its pyramid");
  Check(!pyramid.Reaches(above), "a box behind the light does not");
  Check(!pyramid.Reaches(beside), "a box beside the cone does not");
  Check(pyramid.Reaches(around), "a box around the light does");
}

void TestLightFrameAndSlabs()
{
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetPosition(0, 6, 0);
  light->SetFocalPoint(0, 0, 0);
  light->SetConeAngle(30);
  const vtkLightShaftModel::Light model = vtkLightShaftModel::DescribeLight(light);
  Check(std::abs(model.SquareTangent - std::tan(glm::radians(30.0))) < 1e-12,
    "square tangent of a 30 degree cone");

  // A caster under the light and a prop far beside it.
  vtkNew<vtkPropCollection> props;
  vtkNew<vtkActor> actors[2];
  const double centres[2][3] = { { 0, 2, 0 }, { 20, 2, 0 } };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(centres[i]);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(cube->GetOutputPort());
    actors[i]->SetMapper(mapper);
    props->AddItem(actors[i]);
  }
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0, 3, 12), glm::dvec3(0, 2, 0), glm::dvec3(0, 1, 0));
  const auto camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
  const vtkLightShaftGeometry::LightFrame frame =
    vtkLightShaftGeometry::ComputeLightFrame(model, camera, props, nullptr);
  Check(frame.Casters.size() == 1 && frame.Casters[0] == actors[0].Get(),
    "only the prop under the light casts");
  Check(frame.ShadowsPossible, "shadows are possible");
  Check(frame.Near < 3.5 && frame.Far > 4.5, "light camera's depth range encloses the caster");
  const glm::dvec4 onAxis = frame.WorldToLightClip * glm::dvec4(0, 2, 0, 1);
  Check(std::abs(onAxis.x / onAxis.w) < 1e-12 && std::abs(onAxis.y / onAxis.w) < 1e-12,
    "the light's axis projects to the centre of its square");

  const vtkLightShaftGeometry::LitVolume lit =
    vtkLightShaftGeometry::ComputeLitVolume(frame, camera);
  Check(!lit.Empty() && lit.Nearest > 0.0 && lit.Deepest <= camera.FarDepth * (1 + 1e-9),
    "the lit volume lies in the view volume");
  for (bool jitter : { false, true })
  {
    const auto footprints = vtkLightShaftGeometry::ComputeSlabFootprints(lit, camera, 16, jitter);
    Check(static_cast<int>(footprints.size()) == (jitter ? 17 : 16), "one footprint per slab");
    bool inView = true;
    for (const auto& slab : footprints)
    {
      for (const glm::dvec2& p : slab.Hull)
      {
        inView = inView && std::abs(p.x) <= 1.0 + 1e-9 && std::abs(p.y) <= 1.0 + 1e-9;
      }
    }
    Check(inView, "footprints lie on the screen");
    // A lattice covers exactly the footprint.
    for (int lattice : { 0, 1, 7 })
    {
      std::vector<float> vertices;
      vtkLightShaftGeometry::AppendSlabTriangles(footprints[8], lattice, vertices);
      Check(std::abs(TrianglesArea(vertices) - PolygonArea(footprints[8].Hull)) <
              1e-5 * PolygonArea(footprints[8].Hull),
        "lattice " + std::to_string(lattice) + " covers the footprint once");
    }
  }

  // Looking away from the light: nothing lit in view.
  const glm::dmat4 away =
    glm::lookAt(glm::dvec3(0, 3, 12), glm::dvec3(0, 3, 30), glm::dvec3(0, 1, 0));
  const auto awayCamera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    away, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
  const auto awayFrame =
    vtkLightShaftGeometry::ComputeLightFrame(model, awayCamera, props, nullptr);
  Check(vtkLightShaftGeometry::ComputeLitVolume(awayFrame, awayCamera).Empty(),
    "a light volume behind the camera lights nothing in view");
}

void TestLatticeBudget()
{
  using vtkLightShaftGeometry::AffordableLattice;
  Check(AffordableLattice(0, 100) == 0, "no lattice stays none");
  Check(AffordableLattice(8, 64) == 8, "a small lattice is affordable");
  Check(AffordableLattice(128, 128) == 128, "128 slabs x 128^2 is exactly the budget");
  const int reduced = AffordableLattice(256, 4097);
  Check(reduced == 22 && 4097LL * reduced * reduced <= vtkLightShaftGeometry::LatticeCellBudget,
    "4097 slabs afford a lattice of 22");
  Check(AffordableLattice(256, 1 << 30) == 1, "at least a 1 x 1 lattice");
}
}

int main()
{
  TestPolygons();
  TestCameraAndPyramid();
  TestLightFrameAndSlabs();
  TestLatticeBudget();
  if (Failures > 0)
  {
    std::cerr << Failures << " geometry check(s) failed" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "geometry: all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
