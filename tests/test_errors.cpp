// errors.h: the typed exceptions form one small hierarchy under msmesh::Error (itself a
// std::runtime_error), keep their message, and are what the library throws.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <type_traits>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "msmesh/threads.h"

using namespace msmesh;

TEST(Errors, EveryErrorIsAnErrorAndARuntimeError) {
  static_assert(std::is_base_of_v<std::runtime_error, Error>);
  static_assert(std::is_base_of_v<Error, InvalidInput>);
  static_assert(std::is_base_of_v<Error, SolverError>);
  static_assert(std::is_base_of_v<Error, IoError>);
  static_assert(std::is_base_of_v<Error, Cancelled>);
  // The kinds are distinct: a handler for one does not catch another.
  static_assert(!std::is_base_of_v<InvalidInput, IoError> && !std::is_base_of_v<IoError, InvalidInput>);
  static_assert(!std::is_base_of_v<SolverError, Cancelled> && !std::is_base_of_v<Cancelled, SolverError>);
  const std::string message = "in.ply: vertex 3 has a non-finite coordinate (nan)";
  try {
    throw IoError(message);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
  try {
    throw Cancelled("denoise cancelled");
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "denoise cancelled");
  }
}

TEST(Errors, TheLibraryThrowsTheTypedKinds) {
  EXPECT_THROW(validate_mesh(Eigen::MatrixXd::Zero(3, 2), Eigen::MatrixXi(0, 3)), InvalidInput);
  EXPECT_THROW(set_threads(-1), InvalidInput);
  try {
    validate_mesh(Eigen::MatrixXd::Zero(3, 2), Eigen::MatrixXi(0, 3), "x");
    FAIL() << "expected an error";
  } catch (const Error& e) {  // one handler catches every kind
    EXPECT_NE(std::string(e.what()).find("x: "), std::string::npos) << e.what();
  }
}
