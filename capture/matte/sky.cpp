#include "capture/matte/sky.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace voltree::matte {

namespace {

using Basis = Eigen::Matrix<double, 6, 1>;

Basis BasisAt(double u, double v) {
  Basis b;
  b << 1.0, u, v, u * u, u * v, v * v;
  return b;
}

double NormalizedX(int x, int width) { return (x + 0.5) / width * 2.0 - 1.0; }

struct Sample {
  Basis basis;
  Eigen::Vector3d lab;
};

}  // namespace

cv::Mat SkyModel::Predict(cv::Size size) const {
  cv::Mat out(size, CV_32FC3);
  for (int y = 0; y < size.height; ++y) {
    const double v = NormalizedX(y, size.height);
    auto* row = out.ptr<cv::Vec3f>(y);
    for (int x = 0; x < size.width; ++x) {
      const Basis b = BasisAt(NormalizedX(x, size.width), v);
      for (int c = 0; c < 3; ++c) {
        double value = 0.0;
        for (int k = 0; k < 6; ++k) value += coefficients[c][k] * b[k];
        row[x][c] = static_cast<float>(value);
      }
    }
  }
  return out;
}

SkyModel FitSkyModel(const cv::Mat& lab, const cv::Mat& mask, int max_samples) {
  CV_Assert(lab.type() == CV_32FC3 && mask.type() == CV_8U && lab.size() == mask.size());
  const int count = cv::countNonZero(mask);
  SkyModel model;
  if (count < 12) return model;
  const int stride = std::max(1, count / max_samples);
  std::vector<Sample> samples;
  int seen = 0;
  for (int y = 0; y < lab.rows; ++y) {
    const double v = NormalizedX(y, lab.rows);
    for (int x = 0; x < lab.cols; ++x) {
      if (!mask.at<uint8_t>(y, x) || seen++ % stride) continue;
      const cv::Vec3f p = lab.at<cv::Vec3f>(y, x);
      samples.push_back({BasisAt(NormalizedX(x, lab.cols), v), Eigen::Vector3d(p[0], p[1], p[2])});
    }
  }
  // Trimmed least squares: refit on the samples within 2.5 robust sigmas (tree pixels among the
  // seeds, sun glare) a few times. A small ridge keeps one-row seeds (no v extent) solvable.
  std::vector<char> inlier(samples.size(), 1);
  Eigen::Matrix<double, 6, 3> coefficients = Eigen::Matrix<double, 6, 3>::Zero();
  double sigma = 0.0;
  for (int round = 0; round < 4; ++round) {
    Eigen::Matrix<double, 6, 6> normal = 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
    Eigen::Matrix<double, 6, 3> rhs = Eigen::Matrix<double, 6, 3>::Zero();
    for (size_t i = 0; i < samples.size(); ++i) {
      if (!inlier[i]) continue;
      normal += samples[i].basis * samples[i].basis.transpose();
      rhs += samples[i].basis * samples[i].lab.transpose();
    }
    coefficients = normal.ldlt().solve(rhs);
    std::vector<double> residuals(samples.size());
    for (size_t i = 0; i < samples.size(); ++i)
      residuals[i] = (coefficients.transpose() * samples[i].basis - samples[i].lab).norm();
    std::vector<double> sorted = residuals;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    sigma = 1.4826 * sorted[sorted.size() / 2];
    const double limit = 2.5 * std::max(sigma, 1.0);
    for (size_t i = 0; i < samples.size(); ++i) inlier[i] = residuals[i] <= limit;
  }
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 6; ++k) model.coefficients[c][k] = coefficients(k, c);
  model.sigma = sigma;
  model.samples = static_cast<int>(samples.size());
  return model;
}

cv::Mat SkyDistance(const cv::Mat& lab, const SkyModel& model) {
  const cv::Mat predicted = model.Predict(lab.size());
  cv::Mat difference = lab - predicted, distance;
  cv::Mat squared = difference.mul(difference);
  cv::transform(squared, distance, cv::Matx13f(1, 1, 1));
  cv::sqrt(distance, distance);
  return distance;
}

}  // namespace voltree::matte
