/**
 * @file   vtkLightShaftNoise.h
 * @brief  The tileable density noise of vtkLightShaftPass (private helper, not installed).
 */

#ifndef vtkLightShaftNoise_h
#define vtkLightShaftNoise_h

#include <string> // For the reason an image is unusable
#include <vector> // For the returned texels

class vtkTexture;

/**
 * A size x size tile of fractal gradient noise (octaves of Perlin-style noise whose lattice
 * periods divide the tile, so the tile repeats seamlessly), remapped to non-negative values of
 * mean exactly 1: 1 + 0.8 * n / max|n| with n the zero-mean noise, then renormalised. Row-major,
 * deterministic for a given seed.
 */
std::vector<float> vtkLightShaftTileableNoise(int size, int octaves, unsigned int seed);

/**
 * Rescale `texels` (any non-negative values) to mean 1, in place; an all-zero input becomes all
 * ones. Used for noise images given by the user.
 */
void vtkLightShaftNormalizeNoise(std::vector<float>& texels);

/**
 * A texture's input image (any scalar type, 1-4 components) as RGB floats, row 0 at the bottom;
 * 8-bit images map 255 to 1, others are used as they are (clamped to >= 0). Grey images fill
 * R, G and B. Returns false when there is no usable image: none, or one with a texel that is
 * not finite (then `unusable`, when given, says which, as "texel 7 is nan"). Shared by
 * vtkLightShaftPass and vtkLightShaftReference so both read cookies and noise images the same
 * way.
 */
bool vtkLightShaftImageToRGB(vtkTexture* texture,
  std::vector<float>& rgb,
  int& width,
  int& height,
  std::string* unusable = nullptr);

#endif
