// HDF5 writing helpers shared by the output files: quiet error handling with
// HDF5's most specific message, attributes that can be replaced, datasets that
// grow by rows, and fixed datasets written in one go. Every dataset carries
// `units` and `description` attributes.
#pragma once

#include <H5Cpp.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace icedem {

/// Replaces HDF5's automatic error-stack printing, for the lifetime of the guard, by a
/// recorder of the first error: failures are reported once, through the exception the
/// caller throws, with HDF5's most specific message (see hdf5_reason).
class QuietHdf5 {
 public:
  QuietHdf5();
  ~QuietHdf5();
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// The most specific message HDF5 gave for the failure behind `e` inside the current
/// QuietHdf5 scope (e.g. the errno text of a failed open), else the exception's own message.
std::string hdf5_reason(const H5::Exception& e);

/// Variable-length UTF-8 strings.
H5::StrType utf8_string_type();

/// File access without HDF5's file lock: a run's writer holds its own (dem/output/lock.hpp),
/// and a reader (icedem info, resume) must be able to open the file beside it.
H5::FileAccPropList unlocked_access();

/// Scalar attributes, replaced (not rewritten) so that type and size may change.
void write_attr(const H5::H5Object& obj, const std::string& name, const std::string& value);
void write_attr(const H5::H5Object& obj, const std::string& name, double value);
void write_attr(const H5::H5Object& obj, const std::string& name, uint64_t value);
void write_attr(const H5::H5Object& obj, const std::string& name, int value);

/// A dataset whose first dimension grows by appended rows.
struct Series {
  std::unique_ptr<H5::DataSet> dataset;  // held by pointer: H5 objects must not be assigned
  std::vector<hsize_t> row_shape;        // dimensions after the first
  hsize_t rows = 0;                      // rows written to the file

  /// Appends `count` rows from contiguous memory of type `memtype`.
  void write(const void* data, hsize_t count, const H5::DataType& memtype);
};

/// Datasets written compressed (`compress` below) go through HDF5's shuffle and deflate filters at
/// this level: the fast end, which already takes a field of equal outlines to almost nothing.
inline constexpr int kDeflateLevel = 1;
/// Rows per chunk of a compressed fixed dataset.
inline constexpr hsize_t kFixedChunkRows = 65536;

/// Creates an empty, chunked, extendible dataset of rows of shape `row_shape` in `group`,
/// compressed if `compress`.
Series create_series(const H5::Group& group, const std::string& name, const H5::DataType& type,
                     const std::vector<hsize_t>& row_shape, hsize_t chunk_rows, const std::string& units,
                     const std::string& description, bool compress = false);

/// Opens the dataset `name` of `group` made by create_series, to append after its rows.
Series open_series(const H5::Group& group, const std::string& name);

/// Writes a fixed-size dataset in one go, compressed if `compress`.
void write_fixed(const H5::Group& group, const std::string& name, const H5::DataType& file_type,
                 const H5::DataType& mem_type, const std::vector<hsize_t>& dims, const void* data,
                 const std::string& units, const std::string& description, bool compress = false);

}  // namespace icedem
