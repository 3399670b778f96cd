#include "vtkLightShaftGeometry.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vtkLightShaftGeometry
{
//------------------------------------------------------------------------------
glm::dmat4 FromKeyMatrix(vtkMatrix4x4* key)
{
  return glm::make_mat4(&key->Element[0][0]);
}

glm::dmat4 FromVTKMatrix(vtkMatrix4x4* m)
{
  return glm::transpose(glm::make_mat4(&m->Element[0][0]));
}

void ToVTKMatrix(const glm::dmat4& m, vtkMatrix4x4* out)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      out->SetElement(row, col, m[col][row]);
    }
  }
}

std::array<float, 16> ToFloatColumnMajor(const glm::dmat4& m)
{
  std::array<float, 16> out;
  const double* p = glm::value_ptr(m);
  std::copy(p, p + 16, out.begin());
  return out;
}

std::array<float, 3> ToFloat3(const glm::dvec3& v)
{
  return { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
}

//------------------------------------------------------------------------------
glm::dvec3 BoxCorner(const double bounds[6], int corner)
{
  return glm::dvec3(
    bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
}

//------------------------------------------------------------------------------
std::string CameraFrame::UnusableValue(vtkCamera* camera) const
{
  std::ostringstream text;
  const double* position = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  const double* range = camera->GetClippingRange();
  const double scale = camera->GetParallelScale();
  if (std::equal(position, position + 3, focal))
  {
    text << "its position equals its focal point (" << focal[0] << ", " << focal[1] << ", "
         << focal[2] << ")";
  }
  else if (camera->GetParallelProjection() && !(std::isfinite(scale) && scale > 0.0))
  {
    text << "its parallel scale is " << scale;
  }
  else if (!(std::isfinite(range[0]) && std::isfinite(range[1]) && range[0] < range[1]))
  {
    text << "its clipping range is (" << range[0] << ", " << range[1] << ")";
  }
  else
  {
    const double* matrices[3] = { glm::value_ptr(this->WorldToView),
      glm::value_ptr(this->ViewToClip),
      glm::value_ptr(this->ClipToView) };
    for (const double* m : matrices)
    {
      if (!std::all_of(m, m + 16, [](double v) { return std::isfinite(v); }))
      {
        text << "its view and projection matrices are not finite";
        break;
      }
    }
  }
  return text.str();
}

CameraFrame CameraFrame::FromMatrices(const glm::dmat4& worldToView, const glm::dmat4& viewToClip)
{
  CameraFrame camera;
  camera.WorldToView = worldToView;
  camera.ViewToClip = viewToClip;
  camera.ClipToView = glm::inverse(viewToClip);
  camera.Perspective = viewToClip[2][3] != 0.0;
  const glm::dvec4 farPoint = camera.ClipToView * glm::dvec4(0.0, 0.0, 1.0, 1.0);
  camera.FarDepth = -farPoint.z / farPoint.w;
  return camera;
}

glm::dvec2 CameraFrame::PixelFootprint(int width) const
{
  const double pixel = 2.0 / (width * this->ViewToClip[0][0]);
  return this->Perspective ? glm::dvec2(pixel, 0.0) : glm::dvec2(0.0, pixel);
}

//------------------------------------------------------------------------------
bool Pyramid::Reaches(const double bounds[6]) const
{
  auto outside = [&](const glm::dvec3& normal, double axial)
  {
    // All corners strictly outside the half-space axial * (d . Axis) - d . normal >= 0.
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::dvec3 d = BoxCorner(bounds, corner) - this->Apex;
      if (axial * glm::dot(d, this->Axis) - glm::dot(d, normal) >= 0.0)
      {
        return false;
      }
    }
    return true;
  };
  if (outside(-this->Axis, 0.0))
  {
    return false; // behind the light
  }
  for (const glm::dvec3& side : { this->U, -this->U, this->V, -this->V })
  {
    if (outside(side, this->Tangent))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
double FarthestViewPoint(const CameraFrame& camera, const glm::dvec3& pointVC)
{
  double farthest = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double sx = (corner & 1) ? 1.0 : -1.0;
    const double sy = (corner & 2) ? 1.0 : -1.0;
    const glm::dvec4 nearPoint = camera.ClipToView * glm::dvec4(sx, sy, -1.0, 1.0);
    const glm::dvec4 farPoint = camera.ClipToView * glm::dvec4(sx, sy, 1.0, 1.0);
    const glm::dvec3 n3 = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 f3 = glm::dvec3(farPoint) / farPoint.w;
    const glm::dvec3 dir = f3 - n3;
    const glm::dvec3 start = n3 - dir * (n3.z / dir.z);
    // The corner's ray at the far depth (the backdrop, beyond or before the far plane).
    const glm::dvec3 end = start + dir * ((-camera.FarDepth - start.z) / dir.z);
    farthest = std::max({ farthest, glm::length(start - pointVC), glm::length(end - pointVC) });
  }
  return farthest;
}

//------------------------------------------------------------------------------
int ImagePieceBlockRows(int pieces, int height)
{
  return std::min(std::max(height / (16 * std::max(pieces, 1)), 4), 16);
}

std::vector<RowBlock> ImagePieceRows(int piece, int pieces, int height)
{
  std::vector<RowBlock> rows;
  if (pieces < 1 || piece < 0 || piece >= pieces || height < 1)
  {
    return rows;
  }
  const int block = ImagePieceBlockRows(pieces, height);
  for (int first = piece * block; first < height; first += pieces * block)
  {
    rows.push_back(RowBlock{ first, std::min(first + block, height) });
  }
  return rows;
}

std::vector<RowBlock> GrowRows(const std::vector<RowBlock>& rows, int margin, int height)
{
  std::vector<RowBlock> grown;
  for (const RowBlock& b : rows)
  {
    const RowBlock g{ std::max(b.First - margin, 0), std::min(b.End + margin, height) };
    if (!grown.empty() && g.First <= grown.back().End)
    {
      grown.back().End = std::max(grown.back().End, g.End);
    }
    else
    {
      grown.push_back(g);
    }
  }
  return grown;
}
}
