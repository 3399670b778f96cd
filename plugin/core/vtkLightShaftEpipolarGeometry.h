/**
 * @file   vtkLightShaftEpipolarGeometry.h
 * @brief  The epipolar geometry of a frame, without GL (private, not installed): where the
 *         light's image lies on the screen (the epipole) and the lines through it along which
 *         in-scatter is sampled and interpolated.
 *
 * Epipolar sampling (Engelhardt and Dachsbacher 2010; Chen et al. 2011; Yusov 2013) rests on
 * one fact: along a line of the screen through the light's image, the in-scatter changes
 * smoothly except where the scene's depth jumps, so it can be computed at a few samples of
 * each line and interpolated along and across lines. This file lays the lines out over a
 * width x height target (pixels, origin at the lower-left corner) and answers, for any point of
 * the target, which lines it lies between and where along them: the two directions of that
 * interpolation. Double precision; unit-tested on the CPU (tests/cxx/TestLightShaftGeometry.cxx).
 */

#ifndef vtkLightShaftEpipolarGeometry_h
#define vtkLightShaftEpipolarGeometry_h

#include "vtkLightShaftGeometry.h" // For the camera and light frames

#include <glm/glm.hpp> // For glm vectors

#include <vector> // For the lines' ends

namespace vtkLightShaftEpipolarGeometry
{
/**
 * The light's image on the screen plane: a point (spot and point lights; a directional light's
 * vanishing point), a direction (a point at infinity: a directional light parallel to the
 * screen, or any directional light seen by a parallel camera: the lines are parallel), or
 * undefined (the light at the camera's eye, or a directional light along a parallel camera's
 * axis: every pixel's ray passes through the light's image, and any lines do).
 */
struct Epipole
{
  enum class Kind
  {
    Point,
    AtInfinity,
    Undefined
  };
  Kind Where = Kind::Undefined;
  glm::dvec2 Pixel{ 0.0 };          ///< Point: the image, in pixels (may lie off the target)
  glm::dvec2 Direction{ 1.0, 0.0 }; ///< AtInfinity: unit direction of the lines on the screen
  /// Point, perspective camera: the light (or a directional light's source) lies behind the
  /// camera plane; the lines are the same, the rays run away from it.
  bool Behind = false;
};

/// The epipole of `light` in a width x height target seen through `camera`.
Epipole ComputeEpipole(const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  int width,
  int height);

/**
 * The lines through the epipole that cross a width x height target, `Lines` of them, each
 * sampled at `Samples` points from where it enters the target to where it leaves it.
 *
 * - Radial (the epipole inside the target): the lines run from the epipole to the target's
 *   boundary, their ends evenly spaced along the boundary; line indices are cyclic.
 * - Fan (the epipole off the target or on its boundary): the lines through the epipole whose
 *   exits are evenly spaced along the arc of the boundary facing away from it, from where
 *   they enter the target to where they leave.
 *
 * Samples are evenly spaced along each line between its ends (no sample is wasted off the
 * target), and a point is interpolated from its neighbouring lines at the same fraction of
 * their length: neighbours stay close on targets of ordinary aspect, farther apart in the fan
 * of an epipole beside a sliver of a target.
 * - Parallel (an epipole at infinity, or so far that its lines are parallel to 1e-6 across the
 *   target): lines along Direction, evenly spaced across the target.
 */
struct Layout
{
  enum class Shape
  {
    Radial,
    Fan,
    Parallel
  };
  Shape Form = Shape::Parallel;
  int Width = 1;
  int Height = 1;
  int Lines = 1;
  int Samples = 2;
  glm::dvec2 Origin{ 0.0 }; ///< Radial and Fan: the epipole (pixels)
  /// Radial and Fan: line i leaves the target at perimeter coordinate Start + (i + 0.5) /
  /// Lines * Span (pixels along the boundary, counter-clockwise from the lower-left corner;
  /// Radial: the whole perimeter). Fan: Axis points from the epipole to the target's centre.
  /// Parallel: Axis is the lines' direction, and line i lies at offset Start + (i + 0.5) /
  /// Lines * Span along Normal.
  glm::dvec2 Axis{ 1.0, 0.0 };
  glm::dvec2 Normal{ 0.0, 1.0 };
  double Start = 0.0;
  double Span = 1.0;
  /// Per line: where it enters the target (xy) and leaves it (zw), pixels. A line that only
  /// touches the target has both ends at the same point.
  std::vector<glm::dvec4> Ends;

  /// The point of line `line` at sample position `sample` (0: its entry, Samples - 1: its
  /// exit; fractions in between).
  glm::dvec2 SamplePoint(int line, double sample) const;

  /**
   * Where `p` (pixels) lies: `line`, the fractional index of the lines it lies between (line i
   * passes through p when line == i; in [-0.5, Lines - 0.5], cyclic for Radial), and `sample`,
   * its position along them in samples (0 to Samples - 1, as a fraction of the way from entry
   * to exit along the line through p). False when p lies off the target or at the epipole.
   */
  bool Locate(const glm::dvec2& p, double& line, double& sample) const;
};

/// The layout of `lines` lines (at least 4) of `samples` samples (at least 2) through `epipole`
/// over a width x height target.
Layout ComputeLayout(const Epipole& epipole, int width, int height, int lines, int samples);
}

#endif
