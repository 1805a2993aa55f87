#pragma once
// Helpers for stress-point tests of materials: central finite differences of the stress
// (to check consistent tangents) and a mixed strain/stress control loop (Newton on the
// stress-controlled strain components with the material's own tangent).

#include "materials/elasto_plastic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <vector>

namespace bipot::test {

/// Stress (excluding σ0) at `strain` from `state` (new state discarded).
inline Voigt stress_at(const Material& m, const Voigt& strain, const Voigt& sigma0,
                       const double* state) {
  Voigt s;
  VoigtMatrix D;
  std::vector<double> scratch(m.num_state_variables() + 1);
  m.update(strain, sigma0, state, s, D, scratch.data());
  return s;
}

/// dσ/dε by central differences with step h (engineering shear strains).
inline VoigtMatrix fd_tangent(const Material& m, const Voigt& strain, const Voigt& sigma0,
                              const double* state, double h) {
  const int n = static_cast<int>(strain.size());
  VoigtMatrix D(n, n);
  for (int j = 0; j < n; ++j) {
    Voigt ep = strain, em = strain;
    ep(j) += h;
    em(j) -= h;
    D.col(j) = (stress_at(m, ep, sigma0, state) - stress_at(m, em, sigma0, state)) / (2 * h);
  }
  return D;
}

/// Solves [[a, b], [c, d]] x = (r1, r2) by Cramer's rule: an independent check of the
/// implementations' LU solves in hand-computed returns.
inline std::pair<double, double> cramer(double a, double b, double c, double d, double r1,
                                        double r2) {
  const double det = a * d - b * c;
  return {(d * r1 - b * r2) / det, (a * r2 - c * r1) / det};
}

/// Max-norm relative difference ‖A − B‖∞ / ‖scale‖∞ (scale = B by default; the elastic
/// matrix where B may vanish, as at an apex).
inline double relative_difference(const VoigtMatrix& A, const VoigtMatrix& B) {
  return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
}
inline double relative_difference(const VoigtMatrix& A, const VoigtMatrix& B,
                                  const VoigtMatrix& scale) {
  return (A - B).cwiseAbs().maxCoeff() / scale.cwiseAbs().maxCoeff();
}

/// Columns: unit principal directions for ordered principal values. Frames 0-2 are 2D
/// (Voigt size 4): principal direction `frame` (σ1, σ2 or σ3) along z, which must be
/// principal (the out-of-plane or hoop stress), the other two rotated in the xy plane.
/// Frame 3 is a general 3D rotation.
inline Mat3 principal_frame(int frame) {
  const Mat3 Rz = Eigen::AngleAxisd(0.4, Vec3::UnitZ()).toRotationMatrix();
  if (frame < 3) {
    Mat3 Q;
    int in_plane = 0;
    for (int a = 0; a < 3; ++a)
      Q.col(a) = a == frame ? Vec3(Vec3::UnitZ()) : Vec3(Rz.col(in_plane++));
    return Q;
  }
  return Rz * Eigen::AngleAxisd(1.1, Vec3::UnitY()).toRotationMatrix() *
         Eigen::AngleAxisd(-0.7, Vec3::UnitZ()).toRotationMatrix();
}
inline constexpr int num_frames = 4;
inline int frame_voigt_size(int frame) {
  return frame < 3 ? 4 : 6;
}

/// Puts the ordered principal trial stress in each principal_frame, runs update() with it
/// as the initial stress at zero strain from a virgin state, and expects the total stress
/// Q diag(expected) Qᵀ within `tol` × the largest trial component, the branch code, and a
/// returned stress on the yield surface.
inline void expect_return(const ElastoPlastic& m, const Vec3& trial, const Vec3& expected,
                          int branch, double tol = 1e-10) {
  const double scale = trial.cwiseAbs().maxCoeff();
  for (int frame = 0; frame < num_frames; ++frame) {
    const int n = frame_voigt_size(frame);
    const Mat3 Q = principal_frame(frame);
    const Mat3 T = Q * trial.asDiagonal() * Q.transpose();
    const Voigt sigma0 = stress_voigt(T, n);
    const Voigt want = stress_voigt(Mat3(Q * expected.asDiagonal() * Q.transpose()), n);
    EXPECT_EQ(m.return_stress(T, 0.0).branch, branch) << "frame " << frame;
    Voigt s;
    VoigtMatrix D;
    double state[ElastoPlastic::state_size];
    m.update(Voigt::Zero(n), sigma0, nullptr, s, D, state);
    EXPECT_LT((s + sigma0 - want).cwiseAbs().maxCoeff(), tol * scale)
        << "frame " << frame << "\n got " << (s + sigma0).transpose() << "\nwant "
        << want.transpose();
    EXPECT_NEAR(m.yield_function(stress_tensor(s + sigma0), state[ElastoPlastic::hardening_slot]),
                0.0, tol * scale);
  }
}

/// The tangent against central differences, at a small strain with every component on top
/// of the initial stress whose principal values are `trial`, in each principal_frame. The
/// error is measured against the elastic matrix (the tangent vanishes at an apex).
inline void expect_fd_tangent(const ElastoPlastic& m, const Vec3& trial, int branch,
                              double tol = 1e-6) {
  for (int frame = 0; frame < num_frames; ++frame) {
    const int n = frame_voigt_size(frame);
    const Mat3 Q = principal_frame(frame);
    const Voigt sigma0 = stress_voigt(Mat3(Q * trial.asDiagonal() * Q.transpose()), n);
    // A small strain with every component, so the principal directions rotate.
    Voigt strain(n);
    for (int i = 0; i < n; ++i)
      strain(i) = 1e-5 * (1 + 0.37 * i) * (i % 2 ? -1 : 1);
    Voigt s;
    VoigtMatrix D;
    m.update(strain, sigma0, nullptr, s, D, nullptr);
    EXPECT_EQ(m.return_stress(stress_tensor(sigma0 + m.elasticity_matrix(n) * strain), 0.0).branch,
              branch)
        << "frame " << frame;
    const VoigtMatrix fd = fd_tangent(m, strain, sigma0, nullptr, 1e-9);
    EXPECT_LT(relative_difference(D, fd, m.elasticity_matrix(n)), tol) << "frame " << frame << "\n"
                                                                       << D << "\n\n"
                                                                       << fd;
  }
}

/// Finds the strain whose components with `controlled[i] == false` equal `strain(i)` and
/// whose other components give total stress σ0 + σ = `target(i)`, from the committed
/// `state`; returns the stress (excluding σ0) and writes the new state. Newton with the
/// consistent tangent; `strain` holds the initial guess on entry and the result on exit.
inline Voigt mixed_control(const Material& m, Voigt& strain, const std::vector<bool>& controlled,
                           const Voigt& target, const Voigt& sigma0, const double* state,
                           double* new_state, int max_iterations = 50) {
  const int n = static_cast<int>(strain.size());
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (controlled[i]) free.push_back(i);
  const int k = static_cast<int>(free.size());
  Voigt s;
  VoigtMatrix D;
  for (int it = 0; it < max_iterations; ++it) {
    m.update(strain, sigma0, state, s, D, new_state);
    Eigen::VectorXd r(k);
    Eigen::MatrixXd J(k, k);
    for (int a = 0; a < k; ++a) {
      r(a) = sigma0(free[a]) + s(free[a]) - target(free[a]);
      for (int b = 0; b < k; ++b)
        J(a, b) = D(free[a], free[b]);
    }
    if (k == 0 || r.cwiseAbs().maxCoeff() <= 1e-13 * (1.0 + s.cwiseAbs().maxCoeff())) break;
    const Eigen::VectorXd d = J.fullPivLu().solve(r);
    for (int a = 0; a < k; ++a)
      strain(free[a]) -= d(a);
  }
  m.update(strain, sigma0, state, s, D, new_state);
  return s;
}

} // namespace bipot::test
