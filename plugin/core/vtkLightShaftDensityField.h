/**
 * @file   vtkLightShaftDensityField.h
 * @brief  A medium's density read from a vtkImageData, checked, for vtkLightShaftPass and
 *         vtkLightShaftReference (private, not installed, no GL).
 */

#ifndef vtkLightShaftDensityField_h
#define vtkLightShaftDensityField_h

#include <glm/glm.hpp> // For the texture's placement

#include <cstddef> // For std::size_t
#include <string>  // For the reason an image is refused
#include <vector>  // For the samples and the breakpoints

class vtkDataArray;
class vtkImageData;

/**
 * @class   vtkLightShaftDensityField
 * @brief   The density rho(x) of a medium given as image data, in world coordinates.
 *
 * The rule, in one place: rho is the first component of the named array (point data first,
 * then cell data), or with no name of the point scalars, else the cell scalars. Point data are
 * samples at the image's points; cell data are samples at the cells' centres, held constant
 * across the outer half cell. Inside the image's bounds (the box of its points, placed by its
 * origin, spacing and direction matrix) rho is trilinear between the samples; outside it is 0.
 * The samples are kept as float32, as a GPU texture holds them; everything computed from them
 * is double precision.
 *
 * Along a straight line, rho is a cubic polynomial between the planes where the sample
 * coordinates are integers (and the bounds): Integral() sums two-point Gauss-Legendre over
 * those pieces, which is exact for cubics.
 */
class vtkLightShaftDensityField
{
public:
  /// The largest field read, in samples (512^3: 512 MiB as float32).
  static constexpr std::size_t MaximumSamples = std::size_t(1) << 27;

  /**
   * The array rho is read from, by the rule above: the named one (points, then cells; `cells`
   * says which), else the scalars; nullptr with the reason in `why`.
   */
  static vtkDataArray* FindArray(vtkImageData* image,
    const char* name,
    bool& cells,
    std::string& why);

  /**
   * Reads `image`'s density (see the class description); `arrayName` empty or null: the
   * scalars. Returns "" and replaces this field, or the reason the image cannot be a density
   * field (this field unchanged): no such array or no scalars, fewer than two points along an
   * axis, more than MaximumSamples samples, a value that is not finite or is negative, a
   * spacing, origin or direction matrix that is not finite or not invertible.
   */
  std::string Read(vtkImageData* image, const char* arrayName);

  /// Whether a field was read.
  bool Empty() const { return this->Values.empty(); }

  /// Samples per axis.
  const int* GetSamples() const { return this->Samples; }

  /// The samples, x fastest, as float32.
  const std::vector<float>& GetValues() const { return this->Values; }

  /// Whether the samples sit at cell centres (cell data) rather than at points.
  bool GetCellCentred() const { return this->CellCentred; }

  /// Largest sample value.
  double GetMaximum() const { return this->Maximum; }

  /// rho at world point x (trilinear inside the bounds, 0 outside).
  double Density(const double x[3]) const;

  /// The exact integral of rho along the segment from world point a to world point b.
  double Integral(const double a[3], const double b[3]) const;

  /**
   * Appends to `breaks` the parameters t in (t0, t1) of origin + t dir where rho stops being
   * one cubic (the sample planes and the bounds), sorted.
   */
  void Breakpoints(const double origin[3],
    const double dir[3],
    double t0,
    double t1,
    std::vector<double>& breaks) const;

  /**
   * The integrals of rho along origin + t dir (dir of unit length) from t0 to each of the
   * ascending parameters t[0..n-1] (each at least t0), into out[k * stride]: exact as
   * Integral's, one pass along the ray.
   */
  void Cumulative(const double origin[3],
    const double dir[3],
    double t0,
    const double* t,
    int n,
    float* out,
    int stride) const;

  /**
   * This field resampled to at most `maximum` samples along each axis (an axis with more
   * gets `maximum` points spanning its bounds, trilinear samples of this field), as point
   * data over the same bounds; an axis within it keeps its points (cell data: at most
   * `maximum` of them, so that the grid is within `maximum` too).
   */
  vtkLightShaftDensityField Resampled(int maximum) const;

  /**
   * The grid Resampled(maximum) gives an image of `points` points and `samples` samples per
   * axis: `out` points per axis, and `step`, the image's point index per point of the grid.
   */
  static void ResampledGrid(const int points[3],
    const int samples[3],
    int maximum,
    int out[3],
    double step[3]);

  /**
   * Resampled(maximum) of a larger image this field is a piece of (distributed: each process
   * holds a piece). This field holds that image's samples from `offset` on (its extent's start
   * less the whole's); the whole has `wholePoints` points per axis. Writes the grid's samples
   * of planes [planes[0], planes[1]) (z) whose trilinear neighbours this piece holds into
   * `slab` (those planes of the grid, x fastest), computed exactly as Resampled computes them
   * from the whole image; leaves the others as they are.
   */
  void ResamplePiece(int maximum,
    const int offset[3],
    const int wholePoints[3],
    const int planes[2],
    float* slab) const;

  /**
   * The samples along z of an image of `wholePoints` points (cell data: `cellCentred`) that
   * Resampled(maximum)'s grid plane `plane` reads: [range[0], range[1]], so that a piece holding
   * those planes of samples computes the grid plane with ResamplePiece.
   */
  static void ResampledPlaneSamples(int maximum,
    const int wholePoints[3],
    bool cellCentred,
    int plane,
    int range[2]);

  /**
   * World coordinates to the coordinates of a 3D texture of the samples (texel centres at the
   * samples), and the field's bounds there (the box of its points; outside it rho is 0).
   */
  glm::dmat4 TextureFromWorld() const;
  void TextureBounds(float low[3], float high[3]) const;
  /// The bounds' eight corners in world coordinates (corner c: index box bit k of c).
  void Corners(double corners[8][3]) const;

  /// The sample planes a line along world direction `dir` (unit) crosses per unit length.
  double PlanesPerLength(const double dir[3]) const;

  /// World point to continuous point index relative to the extent's start.
  void ToIndex(const double x[3], double p[3]) const;

private:
  /// rho at continuous point index p.
  double DensityAtIndex(const double p[3]) const;
  /// The parameters in (0, 1) of pa + s (pb - pa) (point indices) where rho's piece changes.
  void IndexBreakpoints(const double pa[3], const double pb[3], std::vector<double>& s) const;

  int Samples[3] = { 0, 0, 0 };
  int Points[3] = { 0, 0, 0 }; ///< the image's dimensions: the bounds are [0, Points - 1]
  bool CellCentred = false;
  double Maximum = 0.0;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double WorldToIndex[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  double IndexToWorld[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  std::vector<float> Values;
};

#endif
