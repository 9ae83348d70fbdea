#include "aerial/spectrum/spectral_data.h"

#include "aerial/spectrum/spectral_data_files.h"

namespace aerial::spectrum {

const std::array<TabulatedSpectrum, 3>& Cie1931ColourMatching() {
  static const std::array<TabulatedSpectrum, 3> cmf = {
      ReadCsvColumn(k_cie_1931_2deg_csv, 1, "cie_1931_2deg.csv"),
      ReadCsvColumn(k_cie_1931_2deg_csv, 2, "cie_1931_2deg.csv"),
      ReadCsvColumn(k_cie_1931_2deg_csv, 3, "cie_1931_2deg.csv")};
  return cmf;
}

const TabulatedSpectrum& SolarIrradiance() {
  static const TabulatedSpectrum solar = ReadCsvColumn(k_solar_irradiance_csv, 1, "solar_irradiance.csv");
  return solar;
}

const TabulatedSpectrum& OzoneCrossSection() {
  static const TabulatedSpectrum ozone =
      ReadCsvColumn(k_ozone_cross_section_csv, 1, "ozone_cross_section.csv");
  return ozone;
}

double YBarIntegralNm() {
  static const double integral = Cie1931ColourMatching()[1].Integral();
  return integral;
}

}  // namespace aerial::spectrum
