// How well computed similarities agree with given ratings: deformseg::evaluation::pearson_correlation and
// deformseg::evaluation::spearman_correlation, as the thesis validates its measure against human ratings.
#include <deformseg/evaluation/correlation.h>

#include <iostream>
#include <vector>

int main() {
  // Similarities of six pairs of animations and the mean rating people gave each pair (1 to 5).
  const std::vector<double> computed{0.95, 0.80, 0.62, 0.40, 0.35, 0.10};
  const std::vector<double> ratings{4.8, 4.1, 4.4, 2.5, 2.0, 1.2};
  const double r = deformseg::evaluation::pearson_correlation(computed, ratings);
  const double rho = deformseg::evaluation::spearman_correlation(computed, ratings);
  std::cout << "Pearson r = " << r << ", Spearman rho = " << rho << '\n';
  return r > 0.9 && rho > 0.9 ? 0 : 1;
}
