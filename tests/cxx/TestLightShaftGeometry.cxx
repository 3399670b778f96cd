// Unit tests of LightShafts::Core's geometry, on the CPU (no GL: linked without OpenGL, run
// without a display): polytope clipping, convex
// hulls and polygon clipping, the camera frame, the light's bounding pyramid and caster
// culling, the light camera, the lit volume, the slab footprints and their lattice, the
// epipole and the epipolar lines; the budget's cost model; and the image pieces' rows and the
// field resampled piece by piece (distributed rendering).
//
// Usage: TestLightShaftGeometry

#include "vtkLightShaftCostModel.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftEnums.h"
#include "vtkLightShaftEpipolarGeometry.h"
#include "vtkLightShaftErrorModel.h"
#include "vtkLightShaftFieldError.h"
#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftGeometryBudget.h"
#include "vtkLightShaftGeometryClipping.h"
#include "vtkLightShaftGeometryLights.h"
#include "vtkLightShaftGeometryLitVolume.h"
#include "vtkLightShaftGeometrySlabs.h"
#include "vtkLightShaftModel.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <iostream>
#include <limits>
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

// A polygonal mapper that only reports its input's bounds: the props of a scene without GL
// (vtkPolyDataMapper::New needs the OpenGL module's factory).
class BoundsOnlyMapper : public vtkPolyDataMapper
{
public:
  static BoundsOnlyMapper* New();
  vtkTypeMacro(BoundsOnlyMapper, vtkPolyDataMapper);
  void RenderPiece(vtkRenderer*, vtkActor*) override {}
};
vtkStandardNewMacro(BoundsOnlyMapper);

// Unit cubes at `centres`, added to `props`; returns their actors.
std::vector<vtkSmartPointer<vtkActor>> AddUnitCubes(vtkPropCollection* props,
  std::initializer_list<std::array<double, 3>> centres)
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const std::array<double, 3>& centre : centres)
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(centre.data());
    vtkNew<BoundsOnlyMapper> mapper;
    mapper->SetInputConnection(cube->GetOutputPort());
    actors.emplace_back(vtkSmartPointer<vtkActor>::New());
    actors.back()->SetMapper(mapper);
    props->AddItem(actors.back());
  }
  return actors;
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
  const std::vector<vtkSmartPointer<vtkActor>> actors =
    AddUnitCubes(props, { { 0, 2, 0 }, { 20, 2, 0 } });
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

// A point light: casters anywhere, six 90-degree cameras, each seeing the casters in its
// pyramid; the lit volume is the whole view volume.
void TestPointLight()
{
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetPosition(0, 3, 0);
  light->SetFocalPoint(0, 0, 0);
  light->SetConeAngle(180);
  const vtkLightShaftModel::Light model = vtkLightShaftModel::DescribeLight(light);
  Check(model.Kind == vtkLightShaftModel::LightKind::Point, "cone angle 180: a point light");
  Check(!model.FallingAttenuation() && model.Exponent == 0.0, "no spot exponent");

  // One caster below the light, one beside it (+X), none above.
  vtkNew<vtkPropCollection> props;
  const std::vector<vtkSmartPointer<vtkActor>> actors =
    AddUnitCubes(props, { { 0, 1, 0 }, { 4, 3, 0 } });
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0, 3, 12), glm::dvec3(0, 2, 0), glm::dvec3(0, 1, 0));
  const auto camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
  const vtkLightShaftGeometry::LightFrame frame =
    vtkLightShaftGeometry::ComputeLightFrame(model, camera, props, nullptr);
  Check(frame.Casters.size() == 2 && frame.ShadowsPossible, "both props can shadow a point light");
  Check(frame.Views.size() == 6, "six cube faces");
  Check(frame.Views[0].Casters.size() == 1 && frame.Views[0].Casters[0] == actors[1].Get(),
    "+X face sees the prop beside the light");
  Check(frame.Views[3].Casters.size() == 1 && frame.Views[3].Casters[0] == actors[0].Get(),
    "-Y face sees the prop below");
  Check(frame.Views[2].Casters.empty(), "+Y face sees nothing");
  Check(frame.Near > 0.0 && frame.Near <= 1.5 && frame.Far >= std::sqrt(4.5 * 4.5 + 0.5) &&
          frame.Far < 6.0,
    "depth range from the nearest to the farthest caster");
  bool centred = true;
  for (int face = 0; face < 6; ++face)
  {
    glm::dvec3 axis(0.0);
    axis[face / 2] = (face % 2) ? -1.0 : 1.0;
    const glm::dvec4 c = frame.Views[face].WorldToClip * glm::dvec4(model.Position + 2.0 * axis, 1);
    centred = centred && std::abs(c.x / c.w) < 1e-12 && std::abs(c.y / c.w) < 1e-12 && c.w > 0;
    // A direction at a face's corner (45 degrees off both axes) projects to the face's corner.
    const glm::dvec3 corner =
      axis + frame.Views[face].ViewUp + glm::cross(axis, frame.Views[face].ViewUp);
    const glm::dvec4 k = frame.Views[face].WorldToClip * glm::dvec4(model.Position + corner, 1);
    centred = centred && std::abs(std::abs(k.x / k.w) - 1.0) < 1e-9 &&
              std::abs(std::abs(k.y / k.w) - 1.0) < 1e-9;
  }
  Check(centred, "each face looks along its axis and spans 90 degrees");
  const auto lit = vtkLightShaftGeometry::ComputeLitVolume(frame, camera);
  Check(!lit.Empty() && lit.Nearest <= 1e-5 * camera.FarDepth &&
          std::abs(lit.Deepest - camera.FarDepth) < 1e-9 * camera.FarDepth,
    "a point light lights the whole view volume");
}

// A directional light: the half-space beyond its plane, an orthographic camera over the part of
// the plane where the lit view volume and the casters overlap.
void TestDirectionalLight()
{
  vtkNew<vtkLight> light;
  light->SetPositional(false);
  light->SetPosition(0, 5, 0); // plane y = 5, light travelling down
  light->SetFocalPoint(0, 3, 0);
  const vtkLightShaftModel::Light model = vtkLightShaftModel::DescribeLight(light);
  Check(model.Kind == vtkLightShaftModel::LightKind::Directional, "not positional: directional");
  Check(std::abs(model.SquareSide - 2.0) < 1e-12, "square side |F - P|");
  Check(
    std::abs(model.Distance(glm::dvec3(3, 1, 2)) - 4.0) < 1e-12, "r: the distance from the plane");

  vtkNew<vtkPropCollection> props;
  // Under the plane in view; above the plane (casts nothing); far away beside the view.
  const std::vector<vtkSmartPointer<vtkActor>> actors =
    AddUnitCubes(props, { { 0, 2, 0 }, { 0, 7, 0 }, { 60, 2, 0 } });
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0, 3, 12), glm::dvec3(0, 2, 0), glm::dvec3(0, 1, 0));
  for (bool parallel : { false, true })
  {
    const auto camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(view,
      parallel ? glm::ortho(-4.0, 4.0, -3.0, 3.0, 0.1, 40.0)
               : glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
    const std::string name = parallel ? " (parallel camera)" : " (perspective camera)";
    const vtkLightShaftGeometry::LightFrame frame =
      vtkLightShaftGeometry::ComputeLightFrame(model, camera, props, nullptr);
    Check(frame.Casters.size() == 1 && frame.Casters[0] == actors[0].Get(),
      "only the prop beyond the plane and over the view casts" + name);
    Check(frame.Views.size() == 1, "one orthographic camera" + name);
    Check(frame.Near >= 0.0 && frame.Near <= 2.5 && frame.Far >= 3.5 && frame.Far < 3.6,
      "depth range: the caster's distances from the plane" + name);
    // The caster's top face lies inside the camera's rectangle, which is no wider than the
    // caster's footprint (plus the margin).
    bool inside = true;
    for (double x : { -0.5, 0.5 })
    {
      for (double z : { -0.5, 0.5 })
      {
        const glm::dvec4 c = frame.WorldToLightClip * glm::dvec4(x, 2.5, z, 1);
        inside = inside && std::abs(c.x) <= 1.0 && std::abs(c.y) <= 1.0 && c.w == 1.0 &&
                 std::abs(c.x) > 0.99 && std::abs(c.y) > 0.99;
      }
    }
    Check(inside, "the camera's rectangle fits the caster's footprint" + name);
    const glm::dvec4 depth = frame.WorldToLightClip * glm::dvec4(0, 2.5, 0, 1);
    const double expected = 2.0 * (2.5 - frame.Near) / (frame.Far - frame.Near) - 1.0;
    Check(std::abs(depth.z - expected) < 1e-9, "orthographic depth is linear in r" + name);
    // The lit volume lies beyond the plane.
    const auto lit = vtkLightShaftGeometry::ComputeLitVolume(frame, camera);
    const glm::dmat4 toWorld = glm::inverse(view);
    bool beyond = !lit.Empty();
    for (const auto& face : lit.Polytope.Faces)
    {
      for (const glm::dvec3& p : face)
      {
        beyond = beyond && (toWorld * glm::dvec4(p, 1.0)).y <= 5.0 + 1e-9;
      }
    }
    Check(beyond, "the lit volume lies beyond the light's plane" + name);
  }

  // The light's plane behind the view (the light travelling towards the camera from behind
  // it... away from the scene): nothing lit.
  vtkNew<vtkLight> away;
  away->SetPositional(false);
  away->SetPosition(0, 3, 14);
  away->SetFocalPoint(0, 3, 20);
  const auto camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
  const auto awayFrame = vtkLightShaftGeometry::ComputeLightFrame(
    vtkLightShaftModel::DescribeLight(away), camera, props, nullptr);
  Check(vtkLightShaftGeometry::ComputeLitVolume(awayFrame, camera).Empty() &&
          !awayFrame.ShadowsPossible,
    "a half-space behind the camera lights nothing in view");
}

void TestLightChoice()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkLight> spot;
  spot->SetPositional(true);
  spot->SetConeAngle(30);
  vtkNew<vtkLight> point;
  point->SetPositional(true);
  point->SetConeAngle(90);
  vtkNew<vtkLight> sun;
  vtkNew<vtkLight> off;
  off->SetPositional(true);
  off->SwitchOff();
  for (vtkLight* light : { spot.Get(), sun.Get(), point.Get(), off.Get() })
  {
    renderer->AddLight(light);
  }
  auto lights = vtkLightShaftModel::FindLights({}, renderer);
  Check(lights.size() == 2 && lights[0] == spot.Get() && lights[1] == point.Get(),
    "automatic: the switched-on spot and point lights, in order");
  lights = vtkLightShaftModel::FindLights({ sun, off }, renderer);
  Check(
    lights.size() == 1 && lights[0] == sun.Get(), "given: any kind, switched-off ones left out");
  Check(vtkLightShaftModel::KindOf(point) == vtkLightShaftModel::LightKind::Point,
    "a cone angle of exactly 90 degrees is a point light");
}

// A hull whose vertices coincide once in float (seen: a screen-filling footprint ending in
// (1, 1) and (1, 1 + 1e-12)) gives no degenerate triangle: llvmpipe dropped whole fans ending in
// one.
void TestNoDegenerateTriangles()
{
  vtkLightShaftGeometry::SlabFootprint slab{
    0, 1.0, { { -1, 1 }, { -1, -1 }, { 1, -1 }, { 1, 1 - 1e-12 }, { 1, 1 } }
  };
  for (int lattice : { 0, 3 })
  {
    std::vector<float> vertices;
    vtkLightShaftGeometry::AppendSlabTriangles(slab, lattice, vertices);
    bool positive = !vertices.empty();
    for (size_t v = 0; v + 11 < vertices.size(); v += 12)
    {
      const double area =
        (double(vertices[v + 4]) - vertices[v]) * (double(vertices[v + 9]) - vertices[v + 1]) -
        (double(vertices[v + 5]) - vertices[v + 1]) * (double(vertices[v + 8]) - vertices[v]);
      positive = positive && area > 0.0;
    }
    Check(positive,
      "every triangle has a positive area in float (lattice " + std::to_string(lattice) + ")");
    Check(std::abs(TrianglesArea(vertices) - 4.0) < 1e-6,
      "and they still cover the footprint (lattice " + std::to_string(lattice) + ")");
  }
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
  Check(AffordableLattice(256, 437, 8) == 24, "eight lights share the lattice cells");
  Check(AffordableLattice(128, 128, 0) == 128, "no lights counted: the whole budget");
}

void TestSegmentBudget()
{
  using vtkLightShaftGeometry::AffordableSamples;
  using vtkLightShaftGeometry::SegmentBudget;
  Check(AffordableSamples(256, 1920LL * 1080) == 256, "256 steps at 1080p are affordable");
  Check(AffordableSamples(4096, 512LL * 512) == 4096, "4096 x 512^2 is exactly the budget");
  const int reduced = AffordableSamples(4096, 640LL * 480);
  Check(reduced == 3495 && 640LL * 480 * reduced <= SegmentBudget &&
          640LL * 480 * (reduced + 1) > SegmentBudget,
    "640x480 affords 3495 steps");
  Check(AffordableSamples(4096, 1920LL * 1080) == 517, "1080p affords 517 steps");
  Check(AffordableSamples(16, 1LL << 40) == 1, "at least one step");
  Check(AffordableSamples(16, 0) == 16, "no pixels: the steps asked for");
  // The lights of a frame share it.
  Check(AffordableSamples(256, 1920LL * 1080, 2) == 256, "two lights at Final fit 1080p");
  Check(AffordableSamples(256, 1920LL * 1080, 3) == 172, "three lights at 1080p: 172 steps");
  Check(AffordableSamples(4096, 640LL * 480, 8) == 436, "eight lights at 640x480: 436 each");
  Check(AffordableSamples(16, 0, 0) == 16, "no lights counted: the steps asked for");
}
}

// The cost model: a setting measured at one resolution predicts the others by its method's
// resolution exponent, so a budget can choose EPIPOLAR at full resolution after measuring it
// at quarter resolution, where its time hardly depends on the pixels.
void TestCostModel()
{
  using Model = vtkLightShaftCostModel;
  const double pixels = 1280.0 * 720.0;
  int epipolar = -1;
  int rayMarch = -1;
  for (int i = 0; i < vtkLightShaftErrorModel::GetNumberOfSettings(); ++i)
  {
    const int method = vtkLightShaftErrorModel::GetSetting(i).Method;
    epipolar = (epipolar < 0 && method == vtkLightShaftEnums::EPIPOLAR) ? i : epipolar;
    rayMarch = (rayMarch < 0 && method == vtkLightShaftEnums::RAY_MARCH) ? i : rayMarch;
  }
  Model model;
  const double prior = model.PredictShafts(epipolar, 4, pixels, 1);
  model.Observe(epipolar, 4, pixels, 1, 0.5, 0.6); // the first frame: one-off costs
  Check(model.PredictShafts(epipolar, 4, pixels, 1) == prior && !model.HasMeasured(),
    "the first frame of a setting is not learnt");
  model.Observe(epipolar, 4, pixels, 1, 0.046, 0.056);
  const double quarter = model.PredictShafts(epipolar, 4, pixels, 1);
  Check(std::abs(quarter - 0.046) < 1e-9, "a measured cost is predicted as measured");
  const double full = model.PredictShafts(epipolar, 1, pixels, 1);
  Check(full > quarter && full < 2.0 * quarter,
    "EPIPOLAR at full resolution costs about what it costs at quarter");
  const double marchFull = model.PredictShafts(rayMarch, 1, pixels, 1);
  const double marchQuarter = model.PredictShafts(rayMarch, 4, pixels, 1);
  Check(marchFull > 2.0 * marchQuarter, "RAY_MARCH at full resolution costs more than at quarter");
  Check(std::abs(model.PredictShafts(epipolar, 1, pixels, 2) - 2.0 * full) < 1e-9 * full,
    "two lit lights cost twice one");
  // Measured at full resolution too, that measurement wins.
  model.Observe(epipolar, 1, pixels, 1, 0.3, 0.31);
  model.Observe(epipolar, 1, pixels, 1, 0.055, 0.065);
  Check(std::abs(model.PredictShafts(epipolar, 1, pixels, 1) - 0.055) < 1e-9,
    "the measured full resolution is predicted as measured");
  // A budget the full resolution fits chooses it.
  const std::vector<vtkLightShaftErrorModel::Features> features(1);
  const Model::Choice choice = model.Choose(0.0667, 0.0, features, true, pixels, 1);
  Check(choice.DownsampleFactor == 1 && choice.Seconds <= 0.0667,
    "a budget that fits EPIPOLAR at full resolution gets full resolution");
}

// The light's image: a point (in front of or behind the camera), a direction (parallel lines)
// or undefined, for each light kind and camera.
void TestEpipole()
{
  using vtkLightShaftEpipolarGeometry::Epipole;
  const int width = 640;
  const int height = 480;
  const glm::dmat4 view(1.0);
  const glm::dmat4 projection = glm::perspective(glm::radians(40.0), 4.0 / 3.0, 0.5, 100.0);
  const auto perspective = vtkLightShaftGeometry::CameraFrame::FromMatrices(view, projection);
  const auto parallel = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::ortho(-4.0, 4.0, -3.0, 3.0, 0.5, 50.0));
  auto pixelOf = [&](const glm::dvec4& h)
  {
    const glm::dvec4 clip = projection * h;
    return glm::dvec2(
      (0.5 * clip.x / clip.w + 0.5) * width, (0.5 * clip.y / clip.w + 0.5) * height);
  };

  vtkLightShaftGeometry::LightFrame spot;
  spot.Model.Kind = vtkLightShaftModel::LightKind::Spot;
  spot.PositionVC = glm::dvec3(1.0, 0.5, -5.0);
  Epipole e = vtkLightShaftEpipolarGeometry::ComputeEpipole(spot, perspective, width, height);
  Check(e.Where == Epipole::Kind::Point && !e.Behind &&
          glm::length(e.Pixel - pixelOf(glm::dvec4(spot.PositionVC, 1.0))) < 1e-9,
    "a spot in front of the camera: its projection");
  spot.PositionVC = glm::dvec3(1.0, 0.5, 5.0);
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(spot, perspective, width, height);
  Check(e.Where == Epipole::Kind::Point && e.Behind &&
          glm::length(e.Pixel - pixelOf(glm::dvec4(spot.PositionVC, 1.0))) < 1e-9,
    "a spot behind the camera: its projection, behind");
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(spot, parallel, width, height);
  Check(e.Where == Epipole::Kind::Point && !e.Behind, "a parallel camera sees a spot's image");
  spot.PositionVC = glm::dvec3(0.0);
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(spot, perspective, width, height);
  Check(e.Where == Epipole::Kind::Undefined, "a light at the eye: no epipole");

  vtkLightShaftGeometry::LightFrame sun;
  sun.Model.Kind = vtkLightShaftModel::LightKind::Directional;
  sun.AxisVC = glm::normalize(glm::dvec3(0.0, -1.0, 1.0)); // from above and ahead
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(sun, perspective, width, height);
  Check(e.Where == Epipole::Kind::Point && !e.Behind &&
          glm::length(e.Pixel - pixelOf(glm::dvec4(-sun.AxisVC, 0.0))) < 1e-9 && e.Pixel.y > height,
    "a sun ahead: its vanishing point, above the picture");
  sun.AxisVC = glm::dvec3(1.0, 0.0, 0.0);
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(sun, perspective, width, height);
  Check(e.Where == Epipole::Kind::AtInfinity && std::abs(std::abs(e.Direction.x) - 1.0) < 1e-12,
    "a sun parallel to the screen: horizontal parallel lines");
  sun.AxisVC = glm::normalize(glm::dvec3(0.0, -1.0, 1.0));
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(sun, parallel, width, height);
  Check(e.Where == Epipole::Kind::AtInfinity && std::abs(std::abs(e.Direction.y) - 1.0) < 1e-12,
    "a parallel camera and a sun: parallel lines along its image");
  sun.AxisVC = glm::dvec3(0.0, 0.0, -1.0);
  e = vtkLightShaftEpipolarGeometry::ComputeEpipole(sun, parallel, width, height);
  Check(e.Where == Epipole::Kind::Undefined, "a sun along a parallel camera's axis: undefined");
}

// Every pixel of the target lies between two neighbouring lines and along them; a line's own
// points are found on it. Returns how far the nearer of the two points a pixel is interpolated
// from (its neighbouring lines, at its fraction of their length) lies from it, at the most.
double CheckLayout(const vtkLightShaftEpipolarGeometry::Layout& layout, const std::string& name)
{
  bool roundTrip = true;
  for (int i = 0; i < layout.Lines; ++i)
  {
    const glm::dvec4& ends = layout.Ends[i];
    if (glm::length(glm::dvec2(ends.z - ends.x, ends.w - ends.y)) < 1e-6)
    {
      continue; // a line that only touches the target
    }
    for (double s : { 0.25, 0.5 * (layout.Samples - 1), layout.Samples - 1.25 })
    {
      double line, sample;
      const bool found = layout.Locate(layout.SamplePoint(i, s), line, sample);
      roundTrip = roundTrip && found && std::abs(line - i) < 1e-6 && std::abs(sample - s) < 1e-6;
    }
  }
  Check(roundTrip, name + ": a line's points are located on it");

  const glm::dvec2 size(layout.Width, layout.Height);
  bool covered = true;
  double farthest = 0.0;
  for (int y = 0; y < layout.Height; y += std::max(layout.Height / 37, 1))
  {
    for (int x = 0; x < layout.Width; x += std::max(layout.Width / 41, 1))
    {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      double line, sample;
      if (!layout.Locate(p, line, sample))
      {
        covered = covered && glm::length(p - layout.Origin) < 1e-6;
        continue;
      }
      covered = covered && line >= -0.5 && line <= layout.Lines - 0.5 && sample >= 0.0 &&
                sample <= layout.Samples - 1;
      // The two lines around p (cyclic when radial), at p's position along them.
      int below = static_cast<int>(std::floor(line));
      int above = below + 1;
      if (layout.Form == vtkLightShaftEpipolarGeometry::Layout::Shape::Radial)
      {
        below = (below + layout.Lines) % layout.Lines;
        above = above % layout.Lines;
      }
      below = std::max(below, 0);
      above = std::min(above, layout.Lines - 1);
      farthest = std::max(farthest,
        std::min(glm::length(layout.SamplePoint(below, sample) - p),
          glm::length(layout.SamplePoint(above, sample) - p)));
    }
  }
  Check(covered, name + ": every pixel lies between two lines, along them");
  return farthest;
}

void TestEpipolarLayout()
{
  using vtkLightShaftEpipolarGeometry::Epipole;
  using vtkLightShaftEpipolarGeometry::Layout;
  // An epipole at (fx, fy) times the target's size.
  auto at = [](double fx, double fy)
  {
    Epipole e;
    e.Where = Epipole::Kind::Point;
    e.Pixel = glm::dvec2(fx, fy);
    return e;
  };
  Epipole infinity;
  infinity.Where = Epipole::Kind::AtInfinity;
  infinity.Direction = glm::dvec2(0.6, 0.8);
  const Epipole undefined;
  const struct
  {
    const char* Name;
    Epipole Light;
    Layout::Shape Form;
  } cases[] = {
    { "epipole at the centre", at(0.5, 0.5), Layout::Shape::Radial },
    { "epipole off-centre", at(0.1, 0.8), Layout::Shape::Radial },
    { "epipole on a corner", at(0.0, 0.0), Layout::Shape::Fan },
    { "epipole on an edge", at(0.3, 1.0), Layout::Shape::Fan },
    { "epipole left of the target", at(-0.5, 0.4), Layout::Shape::Fan },
    { "epipole far below and right", at(200.0, -150.0), Layout::Shape::Fan },
    { "epipole too far for angles", at(1e7, 3e6), Layout::Shape::Parallel },
    { "epipole at infinity", infinity, Layout::Shape::Parallel },
    { "no epipole", undefined, Layout::Shape::Parallel },
  };
  for (const auto& c : cases)
  {
    // An ordinary target, then a sliver (there, where lines from an epipole beside it turn its
    // corners at grazing angles, the interpolated points approach more slowly: only coverage
    // is checked).
    for (const glm::ivec2 size : { glm::ivec2(64, 48), glm::ivec2(3, 200) })
    {
      Epipole light = c.Light;
      light.Pixel *= glm::dvec2(size);
      const std::string name =
        std::string(c.Name) + " (" + std::to_string(size.x) + "x" + std::to_string(size.y) + ")";
      const Layout layout =
        vtkLightShaftEpipolarGeometry::ComputeLayout(light, size.x, size.y, 32, 9);
      Check(layout.Form == c.Form && static_cast<int>(layout.Ends.size()) == 32, name + ": shape");
      const double farthest = CheckLayout(layout, name);
      // The interpolation is local: its points approach the pixel as the lines get denser
      // (where a line's entry turns a corner, neighbours at the same fraction of their lengths
      // are several spacings apart on 32 lines; 8 times the lines, 8 times closer).
      const double denser =
        CheckLayout(vtkLightShaftEpipolarGeometry::ComputeLayout(light, size.x, size.y, 256, 9),
          name + ", 256 lines");
      Check(size.x == 3 || denser <= 0.25 * farthest + 1e-9,
        name + ": 8 times the lines bring the interpolated points at least 4 times closer (" +
          std::to_string(farthest) + " to " + std::to_string(denser) + " pixels)");
    }
  }
  const Layout tiny =
    vtkLightShaftEpipolarGeometry::ComputeLayout(at(0.5, 0.5), 1, 1, 1, 1); // (0.5, 0.5) px
  Check(tiny.Lines == 4 && tiny.Samples == 2, "at least 4 lines of 2 samples");
  CheckLayout(tiny, "a 1x1 target");
}

// A field over [-5, 5]^3 with `n` points along each axis, density(x, y, z) at each.
template<typename F>
vtkSmartPointer<vtkImageData> FieldImage(int n, F density)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetOrigin(-5, -5, -5);
  image->SetSpacing(10.0 / (n - 1), 10.0 / (n - 1), 10.0 / (n - 1));
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double h = 10.0 / (n - 1);
        values->SetValue(id++, density(-5 + i * h, -5 + j * h, -5 + k * h));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void TestFieldError()
{
  // A spot over the origin seen from the side: the probe of a uniform, a layered and no field.
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetPosition(0, 6, 0);
  light->SetFocalPoint(0, 0, 0);
  light->SetConeAngle(30);
  vtkNew<vtkPropCollection> props;
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0, 3, 12), glm::dvec3(0, 2, 0), glm::dvec3(0, 1, 0));
  const auto camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    view, glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 40.0));
  const vtkLightShaftGeometry::LightFrame frame = vtkLightShaftGeometry::ComputeLightFrame(
    vtkLightShaftModel::DescribeLight(light), camera, props, nullptr);
  const std::vector<int> samples{ 16, 0, 256, 16 };

  vtkLightShaftDensityField uniform;
  Check(uniform.Read(FieldImage(3, [](double, double, double) { return 1.0; }), nullptr).empty(),
    "a uniform field reads");
  vtkLightShaftFieldError::Density density;
  density.Field = &uniform;
  density.Scale = 2.0;
  vtkLightShaftFieldError::Probe probe =
    vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  Check(probe.Lit && probe.QuadratureError.size() == samples.size(), "the probe is lit");
  Check(probe.DensityDepth > 2.0 && probe.DensityDepth < 2.0 * 15.0,
    "a uniform field's optical depth: the scale over a lit ray's length");
  bool exact = true;
  for (double e : probe.QuadratureError)
  {
    exact = exact && e < 1e-9;
  }
  Check(exact, "a uniform field has no quadrature error");

  // Density 1 below y = 1, 0 above (linear over one cell of 0.1): the march's samples miss
  // where the edge lies, less with more steps (about as 1/steps).
  vtkLightShaftDensityField layer;
  Check(
    layer
      .Read(FieldImage(101, [](double, double y, double) { return y < 1.0 ? 1.0 : 0.0; }), nullptr)
      .empty(),
    "a layer reads");
  density.Field = &layer;
  density.Scale = 1.0;
  probe = vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  const std::vector<double>& e = probe.QuadratureError;
  Check(e[0] > 0.0 && e[0] > 4.0 * e[2] && e[2] > 0.0,
    "a layer's quadrature error falls with the steps");
  Check(e[1] == 0.0 && e[3] == e[0], "a count of 0 is not measured, a repeated count is the same");
  Check(probe.LightLegError == 0.0, "a marched light leg: no table measured");

  // The light leg's table: its interpolation across the layer's edge errs, less when finer;
  // its term is in every count's error.
  const double coarseTable = vtkLightShaftFieldError::TableError(layer, frame.Model, 16, 0.5);
  const double fineTable = vtkLightShaftFieldError::TableError(layer, frame.Model, 128, 0.5);
  Check(coarseTable > fineTable && fineTable > 0.0, "the table's error falls with its resolution");
  Check(vtkLightShaftFieldError::TableError(layer, frame.Model, 0, 0.5) == 0.0,
    "a marched leg (resolution 0) has no table error");
  density.SigmaT = 0.5;
  density.Scale = 2.0;
  density.TableError = coarseTable;
  const vtkLightShaftFieldError::Probe withTable =
    vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  Check(std::abs(withTable.LightLegError - coarseTable) < 1e-12 &&
          withTable.QuadratureError[2] >= withTable.LightLegError,
    "the table's term is in every count's error");

  // The scene's box: the probe rays end where they leave it, the medium in front of it seen.
  // A floor's box is flat: the air above it is still measured, as much as with no box.
  density.TableError = 0.0;
  const vtkLightShaftFieldError::Probe open =
    vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  const double floor[6] = { -8.0, 8.0, 0.0, 0.0, -8.0, 8.0 };
  std::copy(floor, floor + 6, density.SceneBounds);
  const vtkLightShaftFieldError::Probe overFloor =
    vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  Check(overFloor.DensityDepth > 0.5 * open.DensityDepth && overFloor.QuadratureError[0] > 0.0,
    "the medium above a flat scene is measured");
  const double wall[6] = { -8.0, 8.0, -2.0, 8.0, 11.0, 11.5 }; // just in front of the eye
  std::copy(wall, wall + 6, density.SceneBounds);
  const vtkLightShaftFieldError::Probe blocked =
    vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  Check(blocked.DensityDepth < 0.5 * open.DensityDepth,
    "rays that pass through the scene's box before the lit part end there");

  density.Field = nullptr;
  probe = vtkLightShaftFieldError::Measure(density, frame, camera, samples);
  Check(!probe.Lit && probe.DensityDepth == 0.0, "no field: nothing measured");
}

//------------------------------------------------------------------------------
// Image pieces (distributed rendering): every row of the in-scatter is exactly one piece's, and
// the blocks grown for a gather stay within the image, merged where they meet.
void TestImagePieceRows()
{
  namespace G = vtkLightShaftGeometry;
  for (int pieces : { 1, 2, 3, 4, 64 })
  {
    for (int height : { 1, 7, 120, 300, 2160 })
    {
      std::vector<int> owner(height, -1);
      bool once = true;
      for (int piece = 0; piece < pieces; ++piece)
      {
        for (const G::RowBlock& block : G::ImagePieceRows(piece, pieces, height))
        {
          for (int row = block.First; row < block.End; ++row)
          {
            once = once && owner[row] < 0;
            owner[row] = piece;
          }
        }
      }
      Check(once && std::count(owner.begin(), owner.end(), -1) == 0,
        "image pieces: every row is one piece's (" + std::to_string(pieces) + " pieces, " +
          std::to_string(height) + " rows)");
    }
  }
  const int block = G::ImagePieceBlockRows(2, 600);
  Check(block >= 4 && block <= 16, "image pieces: blocks of 4 to 16 rows");
  Check(G::ImagePieceRows(2, 2, 100).empty() && G::ImagePieceRows(0, 0, 100).empty(),
    "image pieces: no rows for a piece out of range");
  const std::vector<G::RowBlock> grown = G::GrowRows({ { 0, 4 }, { 6, 10 }, { 30, 40 } }, 2, 41);
  Check(grown.size() == 2 && grown[0].First == 0 && grown[0].End == 12 && grown[1].First == 28 &&
          grown[1].End == 41,
    "grown rows: merged where they meet, within the image");
}

//------------------------------------------------------------------------------
// A field resampled piece by piece (each piece with one ghost plane, as ParaView splits an
// image) is Resampled of the whole image, to the bit, for point and for cell data.
void TestResamplePiece()
{
  const int dims[3] = { 23, 17, 13 };
  for (bool cells : { false, true })
  {
    auto image = [&](int zFirst, int zLast)
    {
      vtkNew<vtkImageData> piece;
      piece->SetExtent(0, dims[0] - 1, 0, dims[1] - 1, zFirst, zLast);
      piece->SetOrigin(-1.0, 0.5, 2.0);
      piece->SetSpacing(0.3, 0.2, 0.7);
      const int n[3] = { cells ? dims[0] - 1 : dims[0],
        cells ? dims[1] - 1 : dims[1],
        cells ? zLast - zFirst : zLast - zFirst + 1 };
      vtkNew<vtkDoubleArray> values;
      values->SetNumberOfTuples(vtkIdType(n[0]) * n[1] * n[2]);
      vtkIdType at = 0;
      for (int k = 0; k < n[2]; ++k)
      {
        for (int j = 0; j < n[1]; ++j)
        {
          for (int i = 0; i < n[0]; ++i)
          {
            const int z = zFirst + k;
            values->SetValue(at++, 1.0 + std::sin(0.7 * i) * std::cos(0.4 * j + 0.9 * z));
          }
        }
      }
      (cells ? static_cast<vtkDataSetAttributes*>(piece->GetCellData())
             : static_cast<vtkDataSetAttributes*>(piece->GetPointData()))
        ->SetScalars(values);
      vtkLightShaftDensityField field;
      const std::string why = field.Read(piece, nullptr);
      Check(why.empty(), "resampled pieces: the piece is a field (" + why + ")");
      return field;
    };
    const int maximum = 8;
    const vtkLightShaftDensityField whole = image(0, dims[2] - 1).Resampled(maximum);
    const int* grid = whole.GetSamples();
    std::vector<float> gathered(
      std::size_t(grid[0]) * grid[1] * grid[2], -std::numeric_limits<float>::max());
    const int planes[2] = { 0, grid[2] };
    for (const std::array<int, 2>& z : { std::array<int, 2>{ 0, 5 }, { 4, 9 }, { 8, 12 } })
    {
      const vtkLightShaftDensityField piece = image(z[0], z[1]);
      std::vector<float> slab(gathered.size(), -std::numeric_limits<float>::max());
      const int offset[3] = { 0, 0, z[0] };
      piece.ResamplePiece(maximum, offset, dims, planes, slab.data());
      for (std::size_t i = 0; i < slab.size(); ++i)
      {
        gathered[i] = std::max(gathered[i], slab[i]); // (as the gather's MAX reduction)
      }
    }
    Check(gathered == whole.GetValues(),
      std::string("resampled pieces: the whole image's Resampled, to the bit (") +
        (cells ? "cells" : "points") + ")");
    // Each grid plane from only the samples ResampledPlaneSamples names (the gather reads a
    // piece a few planes at a time): the same plane, to the bit.
    const std::size_t planeSize = std::size_t(grid[0]) * grid[1];
    bool same = true;
    for (int plane = 0; plane < grid[2]; ++plane)
    {
      int range[2];
      vtkLightShaftDensityField::ResampledPlaneSamples(maximum, dims, cells, plane, range);
      const vtkLightShaftDensityField part = image(range[0], range[1] + (cells ? 1 : 0));
      std::vector<float> slab(planeSize, -std::numeric_limits<float>::max());
      const int offset[3] = { 0, 0, range[0] };
      const int one[2] = { plane, plane + 1 };
      part.ResamplePiece(maximum, offset, dims, one, slab.data());
      same =
        same && std::equal(slab.begin(), slab.end(), whole.GetValues().begin() + plane * planeSize);
    }
    Check(same,
      std::string("resampled planes: each from the samples it reads, to the bit (") +
        (cells ? "cells" : "points") + ")");
  }
}

//------------------------------------------------------------------------------
// Cell data resampled along one axis, another axis holding exactly `maximum` cells (one point
// more): the grid has at most `maximum` points along every axis, so that the grid read again
// (the distributed gather's output is read by the pass) is not resampled a second time.
void TestResampledGridWithinMaximum()
{
  const int maximum = 8;
  vtkNew<vtkImageData> image;
  image->SetExtent(0, maximum, 0, 2 * maximum, 0, 3); // cells: 8, 16 and 3
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfTuples(image->GetNumberOfCells());
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, 1.0 + std::sin(0.37 * static_cast<double>(i)));
  }
  image->GetCellData()->SetScalars(values);
  vtkLightShaftDensityField field;
  const std::string why = field.Read(image, nullptr);
  Check(why.empty(), "grid within the maximum: the image is a field (" + why + ")");
  const vtkLightShaftDensityField grid = field.Resampled(maximum);
  const int* samples = grid.GetSamples();
  Check(samples[0] == maximum && samples[1] == maximum && samples[2] == 4,
    "grid within the maximum: cell data resampled to 8 x 8 x 4 points, got " +
      std::to_string(samples[0]) + " x " + std::to_string(samples[1]) + " x " +
      std::to_string(samples[2]));
}

int main()
{
  TestPolygons();
  TestCameraAndPyramid();
  TestLightFrameAndSlabs();
  TestPointLight();
  TestDirectionalLight();
  TestLightChoice();
  TestNoDegenerateTriangles();
  TestLatticeBudget();
  TestSegmentBudget();
  TestCostModel();
  TestEpipole();
  TestEpipolarLayout();
  TestFieldError();
  TestImagePieceRows();
  TestResamplePiece();
  TestResampledGridWithinMaximum();
  if (Failures > 0)
  {
    std::cerr << Failures << " geometry check(s) failed" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "geometry: all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
