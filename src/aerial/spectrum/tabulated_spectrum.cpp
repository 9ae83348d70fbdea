#include "aerial/spectrum/tabulated_spectrum.h"

#include <algorithm>
#include <sstream>

#include "aerial/error.h"

namespace aerial::spectrum {

double TabulatedSpectrum::At(double wavelength_nm) const {
  const std::vector<double>& w = wavelengths_nm;
  if (w.empty() || wavelength_nm < w.front() || wavelength_nm > w.back()) return 0.0;
  size_t upper = std::upper_bound(w.begin(), w.end(), wavelength_nm) - w.begin();
  if (upper == w.size()) return values.back();
  size_t lower = upper - 1;
  double t = (wavelength_nm - w[lower]) / (w[upper] - w[lower]);
  return values[lower] + t * (values[upper] - values[lower]);
}

double TabulatedSpectrum::Integral() const {
  double sum = 0.0;
  for (size_t i = 1; i < values.size(); ++i)
    sum += 0.5 * (values[i - 1] + values[i]) * (wavelengths_nm[i] - wavelengths_nm[i - 1]);
  return sum;
}

TabulatedSpectrum ReadCsvColumn(const std::string& text, int column, const std::string& name) {
  TabulatedSpectrum spectrum;
  std::istringstream lines(text);
  std::string line;
  bool header_seen = false;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::vector<double> cells;
    std::istringstream row(line);
    std::string cell;
    while (std::getline(row, cell, ',')) {
      try {
        size_t used = 0;
        cells.push_back(std::stod(cell, &used));
        if (used != cell.size()) throw std::invalid_argument(cell);
      } catch (const std::exception&) {
        throw Error(name + " line " + std::to_string(line_number), line, "numbers separated by commas");
      }
    }
    if (int(cells.size()) <= column ||
        (!spectrum.wavelengths_nm.empty() && cells[0] <= spectrum.wavelengths_nm.back()))
      throw Error(name + " line " + std::to_string(line_number), line,
                  "a wavelength above the previous row's and " + std::to_string(column) + " value(s)");
    spectrum.wavelengths_nm.push_back(cells[0]);
    spectrum.values.push_back(cells[column]);
  }
  return spectrum;
}

}  // namespace aerial::spectrum
