// Vectorised evaluation over numpy arrays: the inputs are checked once, then every element is
// computed in C++ with the GIL released (no Python call per sample), large arrays split over the
// hardware threads (each element is computed alone, so the values do not depend on how many).
// Results have the inputs' shape plus one axis of `Width` values (RGB, or the four basis
// averages).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <exception>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace matc::python {

// Any array-like of numbers as a C-ordered float64 array (copied only when it is not one).
using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// `value` (a number, a sequence or an array of real numbers) as a C-ordered float64 array, with
// errors that name `argument`: TypeError for complex numbers (their imaginary part would be
// dropped) and values that are not numbers, MemoryError when numpy cannot allocate the copy,
// ValueError for ragged sequences. Never an empty array in place of a failure.
DoubleArray real_array(const pybind11::handle& value, std::string_view argument);

// ValueError naming `argument`, the first bad element and the range when a value is outside
// [0, 1] or NaN.
void check_unit_interval(std::string_view argument, const DoubleArray& values);

// `a` and `b` broadcast against each other, as numpy would, each a C-ordered copy: ValueError
// when the shapes do not broadcast, MemoryError when the copies do not fit, naming both.
std::pair<DoubleArray, DoubleArray> broadcast(const DoubleArray& a, std::string_view a_name,
                                              const DoubleArray& b, std::string_view b_name);

// real_array(value, argument) with every element checked to lie in [0, 1] (check_unit_interval):
// the cosines F takes.
DoubleArray unit_interval_array(const pybind11::handle& value, std::string_view argument);

// ndotv and roughness as every preintegrated evaluation takes them: each a unit_interval_array,
// then broadcast against each other.
std::pair<DoubleArray, DoubleArray> ndotv_roughness_pair(const pybind11::handle& ndotv,
                                                         const pybind11::handle& roughness);

std::vector<pybind11::ssize_t> shape_with_axis(const DoubleArray& values, std::size_t width);

// Elements per thread below which a cheap evaluation stays on one thread (starting a thread
// costs about as much as evaluating F this many times).
inline constexpr std::size_t kElementsPerThread = std::size_t{1} << 15;

// Elements one library call evaluates at once: its results are copied out, so a block bounds
// the memory a call holds beside the result array.
inline constexpr std::size_t kElementsPerCall = 4096;

// body(begin, end) over [0, count) in contiguous chunks of at least `per_thread` elements, one
// chunk per hardware thread at most. An exception a chunk throws (the library's, or
// std::bad_alloc) is thrown again here once every thread has stopped, never std::terminate.
template <typename Body>
void for_each_chunk(std::size_t count, std::size_t per_thread, const Body& body) {
  const std::size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::min(hardware, count / std::max<std::size_t>(per_thread, 1));
  if (threads <= 1) {
    body(std::size_t{0}, count);
    return;
  }
  const std::size_t chunk = (count + threads - 1) / threads;
  std::vector<std::exception_ptr> thrown(threads);
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < threads; ++t) {
      pool.emplace_back([&, t] {
        try {
          body(t * chunk, std::min(count, (t + 1) * chunk));
        } catch (...) {
          thrown[t] = std::current_exception();
        }
      });
    }
    try {
      body(std::size_t{0}, std::min(count, chunk));
    } catch (...) {
      thrown[0] = std::current_exception();
    }
  }
  for (const std::exception_ptr& error : thrown)
    if (error) std::rethrow_exception(error);
}

// call(begin, count) over [begin, end) in blocks of at most kElementsPerCall.
template <typename Call>
void in_blocks(std::size_t begin, std::size_t end, const Call& call) {
  for (std::size_t block = begin; block < end; block += kElementsPerCall)
    call(block, std::min(kElementsPerCall, end - block));
}

// A new array of shape `like`'s + (Width,), filled by fill_rows(begin, end, out) over element
// ranges of at least `per_thread` on each thread, with the GIL released.
template <std::size_t Width, typename FillRows>
pybind11::array_t<double> filled_array(const DoubleArray& like, std::size_t per_thread,
                                       const FillRows& fill_rows) {
  pybind11::array_t<double> out(shape_with_axis(like, Width));
  double* result = out.mutable_data();
  const std::size_t count = static_cast<std::size_t>(like.size());
  {
    pybind11::gil_scoped_release release;
    for_each_chunk(count, per_thread,
                   [&](std::size_t begin, std::size_t end) { fill_rows(begin, end, result); });
  }
  return out;
}

// out[..., :] from blocks: chunk(values, count, out) fills `count` rows of Width values.
template <std::size_t Width, typename Chunk>
pybind11::array_t<double> map_value_chunks(const DoubleArray& values, const Chunk& chunk) {
  const double* in = values.data();
  return filled_array<Width>(values, kElementsPerThread,
                             [&](std::size_t begin, std::size_t end, double* result) {
                               in_blocks(begin, end, [&](std::size_t block, std::size_t count) {
                                 chunk(in + block, count, result + block * Width);
                               });
                             });
}

// out[..., :] from blocks of a pair broadcast(): chunk(a, b, count, out) fills `count` rows of
// Width values.
template <std::size_t Width, typename Chunk>
pybind11::array_t<double> map_pair_chunks(const std::pair<DoubleArray, DoubleArray>& pair,
                                          const Chunk& chunk,
                                          std::size_t per_thread = kElementsPerThread) {
  const auto& [first, second] = pair;
  const double* x = first.data();
  const double* y = second.data();
  return filled_array<Width>(first, per_thread,
                             [&](std::size_t begin, std::size_t end, double* result) {
                               in_blocks(begin, end, [&](std::size_t block, std::size_t count) {
                                 chunk(x + block, y + block, count, result + block * Width);
                               });
                             });
}

// A read-only numpy view of `values` (shape `shape`) that keeps `owner` alive.
template <typename Scalar, typename Owner>
pybind11::array_t<Scalar> read_only_view(const Scalar* values, std::vector<pybind11::ssize_t> shape,
                                         Owner owner) {
  auto* kept = new Owner(std::move(owner));
  pybind11::capsule capsule(kept, [](void* pointer) { delete static_cast<Owner*>(pointer); });
  pybind11::array_t<Scalar> array(std::move(shape), values, capsule);
  pybind11::detail::array_proxy(array.ptr())->flags &=
      ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// A new float64 array (Rows, Columns) holding `rows`.
template <std::size_t Rows, std::size_t Columns>
pybind11::array_t<double> matrix_array(const std::array<std::array<double, Columns>, Rows>& rows) {
  pybind11::array_t<double> array({Rows, Columns});
  auto view = array.mutable_unchecked<2>();
  for (std::size_t r = 0; r < Rows; ++r)
    for (std::size_t c = 0; c < Columns; ++c)
      view(r, c) = rows[r][c];
  return array;
}

// A new float64 array (Size,) holding `values`.
template <std::size_t Size>
pybind11::array_t<double> vector_array(const std::array<double, Size>& values) {
  pybind11::array_t<double> array(Size);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

}  // namespace matc::python
