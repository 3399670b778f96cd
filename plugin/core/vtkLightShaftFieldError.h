/**
 * @file   vtkLightShaftFieldError.h
 * @brief  What a medium from data adds to the error model (private, not installed, no GL):
 *         measured along view rays through a light's lit volume, exactly, from the field.
 */
#ifndef vtkLightShaftFieldError_h
#define vtkLightShaftFieldError_h

#include "vtkLightShaftFieldTable.h" // For the light leg's table
#include "vtkLightShaftGeometry.h"   // For the light and camera frames

#include <vector> // For the errors per sample count

class vtkLightShaftDensityField;

namespace vtkLightShaftFieldError
{
/// The medium's density: scale * rho(x) + background.
struct Density
{
  const vtkLightShaftDensityField* Field = nullptr;
  double Scale = 1.0;
  double Background = 0.0;
  /// The visible props' bounds (xmin, xmax, ...): a view ray that reaches them ends on the
  /// scene's surfaces within them (the probe rays are cut where they leave them); none when
  /// xmin > xmax.
  double SceneBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  /// The medium's largest extinction coefficient (density 1): how much an error of optical
  /// depth dims the shafts.
  double SigmaT = 0.0;
  /// The light leg's table's error (TableError; 0: none, the leg is marched).
  double TableError = 0.0;
};

/**
 * The field seen by a light's shafts: view rays from the camera through points spread over the
 * lit volume, each between the lit volume's view depths, cut to the part the light reaches and
 * to the scene's bounds (where the rays end on a surface, as the pixels' marches do).
 */
struct Probe
{
  bool Lit = false;
  /// The largest optical depth along a probe ray, sigma_t 1: what the homogeneous model's
  /// optical depth feature is for density 1 over the depth range.
  double DensityDepth = 0.0;
  /// For each of `samples` (in order), the field's own relative error at that many steps, the
  /// root of the sum of the squares of three terms measured along the probe rays (0 for a count
  /// of 0: not measured):
  /// - the in-scatter's: the relative RMS error, over the rays and four offsets of the steps,
  ///   of a march's integral of the density (the density at each step's middle, the steps even
  ///   in the march's own variable: distance, or the angle seen from a light that falls off);
  /// - the view leg's extinction: sigma_t times the RMS error of the same march's optical depth;
  /// - the light leg's table's: TableError.
  std::vector<double> QuadratureError;
  /// The light leg's term alone (0: none).
  double LightLegError = 0.0;
};

/**
 * The relative error of the light reaching the scattering medium through `light`'s table
 * through `field` at `resolution` (vtkLightShaftFieldTable::Plan), with `extinction` sigma_t
 * times the density scale: at points the light reaches drawn in proportion to the density
 * over the field's box (where the light scatters), the RMS of extinction times the difference
 * between the table's interpolation and the exact integral from the light, weighted by the
 * light that reaches each point. Depends only on the field, the light, the resolution and the
 * extinction: computed again only when they change.
 */
double TableError(const vtkLightShaftDensityField& field,
  const vtkLightShaftModel::Light& light,
  int resolution,
  double extinction);

/// The probe of `density` for `light` seen by `camera`, for each sample count in `samples`.
Probe Measure(const Density& density,
  const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  const std::vector<int>& samples);
}

#endif
