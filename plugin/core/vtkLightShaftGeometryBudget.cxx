#include "vtkLightShaftGeometryBudget.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftGeometry
{
int AffordableLattice(int requested, int slabs, int lights)
{
  if (requested <= 0)
  {
    return 0;
  }
  const double share = static_cast<double>(LatticeCellBudget) / std::max(lights, 1);
  const int affordable =
    std::max(1, static_cast<int>(std::floor(std::sqrt(share / std::max(slabs, 1)))));
  return std::min(requested, affordable);
}

//------------------------------------------------------------------------------
int AffordableSamples(int requested, long long pixels, int lights)
{
  const long long share = SegmentBudget / std::max(lights, 1);
  const long long affordable = std::max(1LL, share / std::max(pixels, 1LL));
  return static_cast<int>(std::min<long long>(requested, affordable));
}

//------------------------------------------------------------------------------
int AffordableLightVolume(int requested, int faces, int lights, long long pixels)
{
  const double scale = static_cast<double>(FrameLightVolumePixels) /
                       static_cast<double>(std::max(pixels, FrameLightVolumePixels));
  const double share = scale * static_cast<double>(FrameLightVolumeCellAllowance) /
                       (static_cast<double>(std::max(lights, 1)) * std::max(faces, 1));
  const int affordable = std::max(8, static_cast<int>(std::floor(std::sqrt(share))));
  return std::min(requested, affordable);
}

}
