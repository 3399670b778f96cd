#include "vtkLightShaftEpipolarGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vtkLightShaftEpipolarGeometry
{
namespace
{
// An epipole farther than this many target diagonals gives lines parallel to 1e-6 of the
// diagonal across the target: they are laid out as parallel lines (no angles of 1e-7 radians).
constexpr double FarEpipole = 1e6;

double Cross(const glm::dvec2& a, const glm::dvec2& b)
{
  return a.x * b.y - a.y * b.x;
}

// The parameters t where p + t d lies in the target [0, w] x [0, h]; false when it misses.
bool ClipToTarget(const glm::dvec2& p,
  const glm::dvec2& d,
  const glm::dvec2& size,
  double& t0,
  double& t1)
{
  t0 = -std::numeric_limits<double>::infinity();
  t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k)
  {
    if (d[k] == 0.0)
    {
      if (p[k] < 0.0 || p[k] > size[k])
      {
        return false;
      }
      continue;
    }
    double a = -p[k] / d[k];
    double b = (size[k] - p[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t1 >= t0;
}

// The boundary of the target as one coordinate s in [0, 2 (w + h)): along the bottom edge
// (y = 0) to the right, up the right edge, along the top edge to the left, down the left edge.
double PerimeterCoordinate(const glm::dvec2& b, const glm::dvec2& size)
{
  const double distances[4] = {
    std::abs(b.y), std::abs(b.x - size.x), std::abs(b.y - size.y), std::abs(b.x)
  };
  const int edge = static_cast<int>(std::min_element(distances, distances + 4) - distances);
  switch (edge)
  {
    case 0:
      return std::min(std::max(b.x, 0.0), size.x);
    case 1:
      return size.x + std::min(std::max(b.y, 0.0), size.y);
    case 2:
      return size.x + size.y + (size.x - std::min(std::max(b.x, 0.0), size.x));
    default:
      return 2.0 * size.x + size.y + (size.y - std::min(std::max(b.y, 0.0), size.y));
  }
}

std::array<glm::dvec2, 4> Corners(const glm::dvec2& size)
{
  return { glm::dvec2(0.0), glm::dvec2(size.x, 0.0), size, glm::dvec2(0.0, size.y) };
}

glm::dvec2 PerimeterPoint(double s, const glm::dvec2& size)
{
  if (s <= size.x)
  {
    return { s, 0.0 };
  }
  s -= size.x;
  if (s <= size.y)
  {
    return { size.x, s };
  }
  s -= size.y;
  if (s <= size.x)
  {
    return { size.x - s, size.y };
  }
  s -= size.x;
  return { 0.0, size.y - std::min(s, size.y) };
}

// Where the line through p along d enters and leaves the target, as parameters along d; a line
// that misses (only rounding can make one of the layout's lines miss) gets the point nearest
// the target's centre.
void LineEnds(const glm::dvec2& p,
  const glm::dvec2& d,
  const glm::dvec2& size,
  double& t0,
  double& t1)
{
  if (!ClipToTarget(p, d, size, t0, t1))
  {
    t0 = t1 = glm::dot(0.5 * size - p, d);
  }
}
}

//------------------------------------------------------------------------------
Epipole ComputeEpipole(const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  int width,
  int height)
{
  // A spot or point light's position; a directional light's source lies at infinity against
  // the direction its light travels.
  const bool directional = light.Model.Kind == vtkLightShaftModel::LightKind::Directional;
  const glm::dvec4 homogeneous =
    directional ? glm::dvec4(-light.AxisVC, 0.0) : glm::dvec4(light.PositionVC, 1.0);
  const glm::dvec4 clip = camera.ViewToClip * homogeneous;
  const glm::dvec2 half(0.5 * std::max(width, 1), 0.5 * std::max(height, 1));
  const double diagonal = 2.0 * glm::length(half);
  // x and y in pixels from the target's centre, times w.
  const glm::dvec2 scaled(clip.x * half.x, clip.y * half.y);
  const double extent = glm::length(scaled);
  const double scale = glm::length(clip);

  Epipole epipole;
  if (std::max(std::abs(clip.w), extent / diagonal) <= 1e-12 * scale)
  {
    return epipole; // the light at the eye, or along a parallel camera's axis: Undefined
  }
  if (std::abs(clip.w) * FarEpipole * diagonal > extent)
  {
    epipole.Where = Epipole::Kind::Point;
    epipole.Pixel = half + scaled / clip.w;
    epipole.Behind = camera.Perspective && clip.w < 0.0;
    return epipole;
  }
  epipole.Where = Epipole::Kind::AtInfinity;
  epipole.Direction = scaled / extent;
  return epipole;
}

//------------------------------------------------------------------------------
Layout ComputeLayout(const Epipole& epipole, int width, int height, int lines, int samples)
{
  Layout layout;
  layout.Width = std::max(width, 1);
  layout.Height = std::max(height, 1);
  layout.Lines = std::max(lines, 4);
  layout.Samples = std::max(samples, 2);
  const glm::dvec2 size(layout.Width, layout.Height);
  const glm::dvec2 centre = 0.5 * size;
  const double diagonal = glm::length(size);
  layout.Ends.resize(layout.Lines);

  const bool point = epipole.Where == Epipole::Kind::Point &&
                     glm::length(epipole.Pixel - centre) < FarEpipole * diagonal;
  // Strictly inside: from an epipole on the boundary, the lines along its edges would hold
  // no area and leave those edges' points ambiguous; a fan covers that case exactly.
  const bool onTarget = point && epipole.Pixel.x > 0.0 && epipole.Pixel.x < size.x &&
                        epipole.Pixel.y > 0.0 && epipole.Pixel.y < size.y;
  if (point)
  {
    // The lines leave the target through an arc of its boundary, their exits evenly spaced
    // along it (Yusov 2013): no line is wasted, and the lines are densest near the epipole,
    // where the in-scatter changes fastest. From inside (radial) the arc is the whole boundary;
    // from outside (fan) it is the part facing away from the epipole: from the corner seen at
    // the smallest angle, counter-clockwise (increasing perimeter coordinate) to the one at
    // the largest.
    const double perimeter = 2.0 * (size.x + size.y);
    layout.Origin = epipole.Pixel;
    layout.Form = onTarget ? Layout::Shape::Radial : Layout::Shape::Fan;
    layout.Start = 0.0;
    layout.Span = perimeter;
    if (!onTarget)
    {
      layout.Axis = glm::normalize(centre - layout.Origin);
      double lowest = std::numeric_limits<double>::infinity();
      double highest = -lowest;
      glm::dvec2 first(0.0), last(0.0);
      for (const glm::dvec2& corner : Corners(size))
      {
        const glm::dvec2 v = corner - layout.Origin;
        const double angle = std::atan2(Cross(layout.Axis, v), glm::dot(layout.Axis, v));
        if (angle < lowest)
        {
          lowest = angle;
          first = corner;
        }
        if (angle > highest)
        {
          highest = angle;
          last = corner;
        }
      }
      layout.Start = PerimeterCoordinate(first, size);
      const double end = PerimeterCoordinate(last, size);
      layout.Span = (end > layout.Start) ? end - layout.Start : end + perimeter - layout.Start;
    }
    for (int i = 0; i < layout.Lines; ++i)
    {
      const double s = std::fmod(layout.Start + (i + 0.5) / layout.Lines * layout.Span, perimeter);
      const glm::dvec2 d = glm::normalize(PerimeterPoint(s, size) - layout.Origin);
      double t0, t1;
      LineEnds(layout.Origin, d, size, t0, t1);
      t0 = std::max(t0, 0.0); // from inside, the line starts at the epipole
      layout.Ends[i] = glm::dvec4(layout.Origin + t0 * d, layout.Origin + t1 * d);
    }
    return layout;
  }

  // Parallel lines: towards the target from an epipole at infinity or very far away; any
  // direction when the epipole is undefined.
  layout.Form = Layout::Shape::Parallel;
  if (epipole.Where == Epipole::Kind::Point)
  {
    layout.Axis = glm::normalize(centre - epipole.Pixel);
  }
  else if (epipole.Where == Epipole::Kind::AtInfinity)
  {
    layout.Axis = -epipole.Direction;
  }
  layout.Normal = glm::dvec2(-layout.Axis.y, layout.Axis.x);
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (const glm::dvec2& corner : Corners(size))
  {
    lowest = std::min(lowest, glm::dot(corner, layout.Normal));
    highest = std::max(highest, glm::dot(corner, layout.Normal));
  }
  layout.Start = lowest;
  layout.Span = highest - lowest;
  for (int i = 0; i < layout.Lines; ++i)
  {
    const glm::dvec2 foot = (layout.Start + (i + 0.5) / layout.Lines * layout.Span) * layout.Normal;
    double t0, t1;
    LineEnds(foot, layout.Axis, size, t0, t1);
    layout.Ends[i] = glm::dvec4(foot + t0 * layout.Axis, foot + t1 * layout.Axis);
  }
  return layout;
}

//------------------------------------------------------------------------------
glm::dvec2 Layout::SamplePoint(int line, double sample) const
{
  const glm::dvec4& ends = this->Ends[line];
  const double f = sample / (this->Samples - 1);
  return glm::mix(glm::dvec2(ends.x, ends.y), glm::dvec2(ends.z, ends.w), f);
}

//------------------------------------------------------------------------------
bool Layout::Locate(const glm::dvec2& p, double& line, double& sample) const
{
  const glm::dvec2 size(this->Width, this->Height);
  const double tolerance = 1e-9 * glm::length(size);
  if (p.x < -tolerance || p.y < -tolerance || p.x > size.x + tolerance || p.y > size.y + tolerance)
  {
    return false;
  }
  // The line through p and the fraction of the way along it from its entry to its exit.
  double fraction = 0.0;
  if (this->Form == Shape::Parallel)
  {
    const double offset = glm::dot(p, this->Normal);
    line = (offset - this->Start) / this->Span * this->Lines - 0.5;
    const glm::dvec2 foot = offset * this->Normal;
    double t0, t1;
    LineEnds(foot, this->Axis, size, t0, t1);
    const double t = glm::dot(p, this->Axis);
    fraction = (t1 > t0) ? (t - t0) / (t1 - t0) : 0.0;
  }
  else
  {
    const glm::dvec2 v = p - this->Origin;
    const double distance = glm::length(v);
    if (distance <= tolerance)
    {
      return false; // the epipole itself: on every line
    }
    const glm::dvec2 d = v / distance;
    double t0, t1;
    LineEnds(this->Origin, d, size, t0, t1);
    t0 = std::max(t0, 0.0); // from inside, the line starts at the epipole
    // Where the line leaves the target, along the arc from Start (wrapping once round).
    double along = PerimeterCoordinate(this->Origin + t1 * d, size) - this->Start;
    if (along < -tolerance)
    {
      along += 2.0 * (size.x + size.y);
    }
    line = along / this->Span * this->Lines - 0.5;
    fraction = (t1 > t0) ? (distance - t0) / (t1 - t0) : 0.0;
  }
  line = std::min(std::max(line, -0.5), this->Lines - 0.5);
  sample = std::min(std::max(fraction, 0.0), 1.0) * (this->Samples - 1);
  return true;
}
}
