#pragma once
// A function of wavelength given at tabulated wavelengths, read between them by linear
// interpolation and zero outside them (as the CIE tables are used: CIE 015:2018, 7.2.1).
#include <string>
#include <vector>

namespace aerial::spectrum {

struct TabulatedSpectrum {
  std::vector<double> wavelengths_nm;  // increasing
  std::vector<double> values;

  double At(double wavelength_nm) const;
  // Trapezoidal integral over the table's range.
  double Integral() const;
};

// Reads column `column` (1 = the first after the wavelength) of a CSV text whose comment lines
// start with '#' and whose first other line is the header. Throws aerial::Error naming `name` and
// the line if a row is malformed or the wavelengths do not increase.
TabulatedSpectrum ReadCsvColumn(const std::string& text, int column, const std::string& name);

}  // namespace aerial::spectrum
