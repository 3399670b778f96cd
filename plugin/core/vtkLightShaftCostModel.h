/**
 * @file   vtkLightShaftCostModel.h
 * @brief  What each sampling setting costs on this machine, learnt from the frames it renders,
 *         and the most accurate one a frame budget allows (private, not installed).
 */

#ifndef vtkLightShaftCostModel_h
#define vtkLightShaftCostModel_h

#include "vtkLightShaftErrorModel.h" // For the features and the ladder

#include <array>  // For the per-factor costs
#include <vector> // For the per-setting costs

/**
 * @class   vtkLightShaftCostModel
 * @brief   Seconds per in-scatter pixel and lit light for each setting of the error model's
 *          ladder at full, half and quarter resolution, and the seconds of the rest of a frame
 *          (scene, composite), learnt from measured frames; the choice of a setting under a
 *          budget.
 *
 * Before a setting has been measured its cost is its prior (the ladder's median time over the
 * plain frame on the held-out random scenes, docs/random-scenes.md, per pixel at any
 * resolution) times this machine's scale, the geometric mean of what the measured settings
 * cost over their priors; before anything is measured, the scale of the 2-core llvmpipe the
 * priors were measured on. A setting measured at one resolution predicts its cost at the
 * others by how its method's time follows the in-scatter's pixels (EPIPOLAR's hardly: its
 * lines' samples do not depend on them). Each
 * measurement moves a setting's cost halfway to what was measured (in log), so a change of
 * machine load is followed within a few frames.
 */
class vtkLightShaftCostModel
{
public:
  vtkLightShaftCostModel();

  /// The downsample factors a budget may use, most accurate first.
  static constexpr std::array<int, 3> Factors = { 1, 2, 4 };

  struct Choice
  {
    int Setting = -1;         ///< the ladder's index
    int DownsampleFactor = 1; ///< one of Factors
    double Seconds = 0.0;     ///< predicted for the whole frame
    double Error = -1.0;      ///< the error model's prediction (at full resolution)
  };

  /**
   * The most accurate choice predicted to fit `budget` seconds for a frame of `pixels`
   * (viewport) pixels and `lights` lit lights (a choice not measured yet must fit 85% of it
   * when its setting was measured at another resolution, 60% when never measured): full resolution
   * before half before quarter, then the lowest predicted error; with a `target` error, the
   * cheapest of those that fit and meet it at full resolution (the error model knows no other).
   * When nothing fits, the cheapest. Without `closedForm` (a cookie or noise) the LIGHT_VOLUME
   * settings are left out.
   */
  Choice Choose(double budget,
    double target,
    const std::vector<vtkLightShaftErrorModel::Features>& features,
    bool closedForm,
    double pixels,
    int lights) const;

  /// Predicted seconds of the shafts alone with `setting` at `factor`; in `trust` (when given)
  /// the part of a budget the prediction may fill (see LogCostOf).
  double PredictShafts(int setting,
    int factor,
    double pixels,
    int lights,
    double* trust = nullptr) const;
  /// Predicted seconds of the rest of the frame (scene, composite) for `pixels`.
  double PredictRest(double pixels) const;

  /// A measured frame: its shafts took `shafts` seconds with `setting` at `factor`, the whole
  /// frame `total` seconds. Learnt only when the frame before was measured with the same
  /// setting and factor (the first after a change pays one-off costs).
  void Observe(int setting, int factor, double pixels, int lights, double shafts, double total);

  /// Whether anything has been measured.
  bool HasMeasured() const { return this->Measurements > 0; }

private:
  static int FactorIndex(int factor);
  double LogScale() const;
  /// Log seconds per (in-scatter pixel x lit light) of `setting` at `factor`, and in `trust`
  /// (when given) the part of a budget its prediction may fill: MeasuredTrust,
  /// ExtrapolatedTrust (the setting measured at another factor) or PriorTrust.
  double LogCostOf(int setting, int factor, double* trust) const;
  static constexpr double MeasuredTrust = 1.0;
  static constexpr double ExtrapolatedTrust = 0.85;
  static constexpr double PriorTrust = 0.6;

  /// Log seconds per (in-scatter pixel x lit light), per setting and factor; NaN: unmeasured.
  std::vector<std::array<double, 3>> LogCost;
  double LogRestPerPixel;
  int Measurements = 0;
  int LastSetting = -1; ///< the setting and factor of the last frame observed
  int LastFactor = 0;
};

#endif
