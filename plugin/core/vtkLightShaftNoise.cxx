#include "vtkLightShaftNoise.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace
{
double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
}

std::vector<float> vtkLightShaftTileableNoise(int size, int octaves, unsigned int seed)
{
  size = std::max(size, 1);
  std::vector<double> sum(static_cast<size_t>(size) * size, 0.0);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * 3.14159265358979323846);
  double amplitude = 1.0;
  for (int octave = 0, period = 4; octave < octaves && period <= size; ++octave, period *= 2)
  {
    // Unit gradients on a period x period lattice that wraps around: the tile repeats.
    std::vector<double> gx(static_cast<size_t>(period) * period);
    std::vector<double> gy(gx.size());
    for (size_t i = 0; i < gx.size(); ++i)
    {
      const double a = angle(random);
      gx[i] = std::cos(a);
      gy[i] = std::sin(a);
    }
    const double cell = static_cast<double>(size) / period;
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        const double u = (x + 0.5) / cell;
        const double v = (y + 0.5) / cell;
        const int i0 = static_cast<int>(std::floor(u));
        const int j0 = static_cast<int>(std::floor(v));
        const double fu = u - i0;
        const double fv = v - j0;
        auto dotGradient = [&](int i, int j, double dx, double dy)
        {
          const size_t k = static_cast<size_t>((j % period) * period + (i % period));
          return gx[k] * dx + gy[k] * dy;
        };
        const double n00 = dotGradient(i0, j0, fu, fv);
        const double n10 = dotGradient(i0 + 1, j0, fu - 1.0, fv);
        const double n01 = dotGradient(i0, j0 + 1, fu, fv - 1.0);
        const double n11 = dotGradient(i0 + 1, j0 + 1, fu - 1.0, fv - 1.0);
        const double sx = Fade(fu);
        const double sy = Fade(fv);
        const double n0 = n00 + sx * (n10 - n00);
        const double n1 = n01 + sx * (n11 - n01);
        sum[static_cast<size_t>(y) * size + x] += amplitude * (n0 + sy * (n1 - n0));
      }
    }
    amplitude *= 0.5;
  }
  const double mean = std::accumulate(sum.begin(), sum.end(), 0.0) / sum.size();
  double peak = 0.0;
  for (double& value : sum)
  {
    value -= mean;
    peak = std::max(peak, std::abs(value));
  }
  std::vector<float> texels(sum.size());
  for (size_t i = 0; i < sum.size(); ++i)
  {
    texels[i] = static_cast<float>(1.0 + (peak > 0.0 ? 0.8 * sum[i] / peak : 0.0));
  }
  vtkLightShaftNormalizeNoise(texels);
  return texels;
}

void vtkLightShaftNormalizeNoise(std::vector<float>& texels)
{
  double total = 0.0;
  for (float& value : texels)
  {
    value = std::max(value, 0.0f);
    total += value;
  }
  if (texels.empty())
  {
    return;
  }
  const double mean = total / texels.size();
  for (float& value : texels)
  {
    value = mean > 0.0 ? static_cast<float>(value / mean) : 1.0f;
  }
}

bool vtkLightShaftImageToRGB(vtkTexture* texture,
  std::vector<float>& rgb,
  int& width,
  int& height,
  std::string* unusable)
{
  if (!texture)
  {
    return false;
  }
  if (texture->GetNumberOfInputPorts() > 0 && texture->GetNumberOfInputConnections(0) > 0)
  {
    texture->GetInputAlgorithm()->Update();
  }
  auto* image = vtkImageData::SafeDownCast(texture->GetInputDataObject(0, 0));
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetNumberOfTuples() == 0)
  {
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  width = dims[0];
  height = dims[1];
  if (width < 1 || height < 1 || scalars->GetNumberOfTuples() < vtkIdType(width) * height)
  {
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  const double scale = scalars->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  rgb.resize(static_cast<size_t>(width) * height * 3);
  for (vtkIdType i = 0; i < vtkIdType(width) * height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int source = (components >= 3) ? c : 0; // grey (+ alpha) images: grey in R, G, B
      const double value = scalars->GetComponent(i, source) * scale;
      if (!std::isfinite(value))
      {
        if (unusable)
        {
          *unusable = "texel " + std::to_string(i) + " is " + std::to_string(value);
        }
        return false;
      }
      rgb[i * 3 + c] = static_cast<float>(std::max(value, 0.0));
    }
  }
  return true;
}
