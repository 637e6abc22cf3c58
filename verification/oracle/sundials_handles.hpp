#pragma once
// Owners of the SUNDIALS objects the solvers share: a SUNDIALS context and a serial vector, each
// freed by its destructor. SUNDIALS is a C library, so this is where its lifetimes become RAII.

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cstddef>
#include <new>
#include <stdexcept>
#include <type_traits>

namespace gp::oracle {

// The oracle hands SUNDIALS arrays of double.
static_assert(std::is_same_v<sunrealtype, double>, "SUNDIALS must be built with double precision");

class SundialsContext {
 public:
  SundialsContext() {
    if (SUNContext_Create(nullptr, &context_) != 0) {
      throw std::runtime_error("SUNDIALS: could not create a context");
    }
  }
  ~SundialsContext() { SUNContext_Free(&context_); }
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;

  SUNContext get() const { return context_; }

 private:
  SUNContext context_ = nullptr;
};

/// A serial N_Vector of `size` doubles.
class SerialVector {
 public:
  SerialVector(std::size_t size, SUNContext context)
      : vector_(N_VNew_Serial(static_cast<sunindextype>(size), context)) {
    if (vector_ == nullptr) throw std::bad_alloc();
  }
  ~SerialVector() { N_VDestroy(vector_); }
  SerialVector(const SerialVector&) = delete;
  SerialVector& operator=(const SerialVector&) = delete;

  N_Vector get() const { return vector_; }
  double* data() const { return N_VGetArrayPointer(vector_); }

 private:
  N_Vector vector_;
};

}  // namespace gp::oracle
