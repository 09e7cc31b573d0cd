#pragma once
// Spatial polarisation of EME paths (docs/eme.md), as WSJT-X's Astronomical Data window shows
// it (WSJTX/wsjtx lib/astro.f90, the "spatial polarization offset" block; its user guide,
// astro_data.adoc). A linearly polarised antenna that is level at each station sees the Moon's
// reflection turned by the difference of the two stations' parallactic angles; for self echoes
// the two ends are one station and the spatial offset is zero (only Faraday rotation remains,
// which nobody predicts). Pure functions of angles in degrees.

namespace azt::eme {

/// The parallactic angle of a direction seen at latitude `lat_deg` (WSJT-X's `poloffset` of one
/// station): atan2(cos φ·sin A, sin φ·cos E − cos φ·cos A·sin E), degrees in (−180, 180].
double parallactic_angle_deg(double lat_deg, double az_deg, double el_deg);

/// Dpol between two stations: their parallactic angles' difference (DX minus own) folded to
/// (−90, 90] (a linear polarisation is the same turned by 180°). Positive: turn the antenna
/// clockwise looking from behind it towards the Moon (WSJT-X's convention).
double dpol_deg(double own_parallactic_deg, double dx_parallactic_deg);

/// MNR, the maximum non-reciprocity of the path (dB) for a spatial offset: −20·log10|cos 2·Dpol|,
/// capped at 25 dB (|cos 2·Dpol| ≥ 0.056234), as WSJT-X computes it.
double mnr_db(double dpol_deg);

}  // namespace azt::eme
