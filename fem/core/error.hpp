#pragma once
/// User-facing errors. They are exceptions with context and are always on (no NDEBUG switch).

#include <stdexcept>
#include <string>
#include <vector>

namespace bipot {

/// Base of every error bipot reports to a user.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Invalid input: YAML, parameters, meshes. Holds every problem found, one line each,
/// formatted `file:line:col: key.path: message` when a location is known.
class InputError : public Error {
public:
  explicit InputError(std::vector<std::string> problems);
  explicit InputError(const std::string& problem) : InputError(std::vector<std::string>{problem}) {}
  const std::vector<std::string>& problems() const { return problems_; }

private:
  std::vector<std::string> problems_;
};

/// A solver that did not converge: the message names the stage, step, iteration and residual.
class SolverError : public Error {
public:
  using Error::Error;
};

} // namespace bipot
