/**
 * @file   vtkLightShaftGeometryBudget.h
 * @brief  What one frame may afford, without GL (private, not installed): the bounds of a
 *         frame's lattice cells, segments, radial samples and light-volume cells, and the
 *         sampling that fits them (part of the namespace vtkLightShaftGeometry,
 *         vtkLightShaftGeometry.h).
 */

#ifndef vtkLightShaftGeometryBudget_h
#define vtkLightShaftGeometryBudget_h

namespace vtkLightShaftGeometry
{

/// Lattice cells built and drawn in one frame at most, shared equally by the lights that
/// radiate: the cells are clipped on the CPU, so their number bounds the frame's CPU time
/// (about 1.5 s for 2^21 cells here: docs/any-scene.md).
constexpr long long LatticeCellBudget = 1LL << 21;

/// The lattice resolution that `slabs` slabs of one of `lights` lights can afford within
/// LatticeCellBudget: `requested`, or the largest n with lights * slabs * n^2 within the budget
/// (at least 1).
int AffordableLattice(int requested, int slabs, int lights = 1);

/// Segments (a step of a march, a slab across a pixel: one closed-form integral and one
/// lookup each) a frame's in-scatter integrates at most, counted over the in-scatter's pixels
/// and shared equally by the lights that radiate: the bound of a frame's time at the sampling
/// maxima (about 16 s here, 15 ns a segment on llvmpipe with 2 cores: docs/any-scene.md
/// ).
constexpr long long SegmentBudget = 1LL << 30;

/// Segments one frame integrates at most where a setting's work is spread over frames
/// (vtkLightShaftPass::SplitLongFrames, with progressive refinement): a sixteenth of
/// SegmentBudget, at most about 2 s a frame here (up to 25 ns a segment: RAY_MARCH with four
/// spotlights and 4096² maps at 640x480; docs/robustness.md).
constexpr long long FrameSegmentAllowance = SegmentBudget / 16;

/// RADIAL_BLUR's samples (one occlusion-buffer fetch each) one frame takes at most where a
/// setting's work is spread over frames, counted over the in-scatter's pixels and shared by the
/// lights: 16 FrameSegmentAllowance, a blur sample being about 20 times cheaper than a segment
/// (0.7-0.8 ns on llvmpipe with 2 cores: 1024 samples with eight lights at 1080p, 12.9 s).
constexpr long long FrameRadialSampleAllowance = 16 * FrameSegmentAllowance;

/// LIGHT_VOLUME's mesh cells (over each map, each cube face of a point light's) one frame draws
/// at most where a setting's work is spread over frames (SplitLongFrames, with progressive
/// refinement), shared by the lights that radiate, up to FrameLightVolumePixels in-scatter
/// pixels, and in inverse proportion to them beyond (the cells' fragments): four spotlights'
/// 1024^2 at 640x480 (1.3 s a frame here); at 1080p eight lights' 287^2. Measured on llvmpipe
/// with 2 cores, 1080p, eight spotlights: about 0.7 s each 2^20 cells, and 1.5 s a frame
/// besides. A closed mesh's parts do not add up to pictures a frame could show alone, so it is
/// not split: a frame over it draws a coarser mesh.
constexpr long long FrameLightVolumeCellAllowance = 1LL << 22;
constexpr long long FrameLightVolumePixels = 640 * 480;

/// The light-volume mesh resolution one of `lights` lights with `faces` faces (6: a point
/// light's cube) can afford within FrameLightVolumeCellAllowance over `pixels` in-scatter
/// pixels: `requested`, or the largest n with lights * faces * n^2 within it (at least 8, the
/// parameter's minimum).
int AffordableLightVolume(int requested, int faces, int lights, long long pixels);

/// The steps or slabs per pixel that `pixels` in-scatter pixels of one of `lights` lights can
/// afford within SegmentBudget: `requested`, or fewer (at least 1).
int AffordableSamples(int requested, long long pixels, int lights = 1);
}

#endif
