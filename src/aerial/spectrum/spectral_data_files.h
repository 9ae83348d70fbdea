#pragma once
// The text of src/aerial/spectrum/data/*.csv, embedded by cmake/SpectralData.cmake.
namespace aerial::spectrum {

extern const char* const k_cie_1931_2deg_csv;
extern const char* const k_solar_irradiance_csv;
extern const char* const k_ozone_cross_section_csv;

}  // namespace aerial::spectrum
