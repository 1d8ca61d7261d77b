#include "dem/core/hdf5_io.hpp"

#include <algorithm>

namespace icedem {
namespace {

// innermost description of the first HDF5 failure inside the current QuietHdf5 scope
thread_local std::string first_hdf5_error;

// collects the description of the innermost (first-raised) error on an HDF5 error stack
herr_t collect_innermost(unsigned n, const H5E_error2_t* err, void* out) {
  if (n == 0 && err->desc != nullptr) *static_cast<std::string*>(out) = err->desc;
  return 0;
}

// HDF5 calls this when an API call fails, while its error stack is still intact
herr_t record_error(hid_t stack, void*) {
  if (first_hdf5_error.empty()) H5Ewalk2(stack, H5E_WALK_UPWARD, collect_innermost, &first_hdf5_error);
  return 0;
}

}  // namespace

QuietHdf5::QuietHdf5() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, record_error, nullptr);
  first_hdf5_error.clear();
}

QuietHdf5::~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

std::string hdf5_reason(const H5::Exception& e) {
  return first_hdf5_error.empty() ? e.getDetailMsg() : first_hdf5_error;
}

H5::StrType utf8_string_type() {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

// attributes are replaced, not rewritten, so that type and size may change between writes
void write_attr(const H5::H5Object& obj, const std::string& name, const std::string& value) {
  if (obj.attrExists(name)) obj.removeAttr(name);
  H5::StrType type = utf8_string_type();
  H5::Attribute attr = obj.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
  attr.write(type, value);
}

void write_attr(const H5::H5Object& obj, const std::string& name, double value) {
  if (obj.attrExists(name)) obj.removeAttr(name);
  H5::Attribute attr =
      obj.createAttribute(name, H5::PredType::IEEE_F64LE, H5::DataSpace(H5S_SCALAR));
  attr.write(H5::PredType::NATIVE_DOUBLE, &value);
}

void write_attr(const H5::H5Object& obj, const std::string& name, uint64_t value) {
  if (obj.attrExists(name)) obj.removeAttr(name);
  H5::Attribute attr =
      obj.createAttribute(name, H5::PredType::STD_U64LE, H5::DataSpace(H5S_SCALAR));
  attr.write(H5::PredType::NATIVE_UINT64, &value);
}

void write_attr(const H5::H5Object& obj, const std::string& name, int value) {
  if (obj.attrExists(name)) obj.removeAttr(name);
  H5::Attribute attr =
      obj.createAttribute(name, H5::PredType::STD_I32LE, H5::DataSpace(H5S_SCALAR));
  attr.write(H5::PredType::NATIVE_INT, &value);
}

void Series::write(const void* data, hsize_t count, const H5::DataType& memtype) {
  if (count == 0) return;
  std::vector<hsize_t> dims{rows + count};
  dims.insert(dims.end(), row_shape.begin(), row_shape.end());
  dataset->extend(dims.data());

  // select the new rows in the file, the whole buffer in memory
  std::vector<hsize_t> start(dims.size(), 0), block = dims;
  start[0] = rows;
  block[0] = count;
  rows += count;
  hsize_t elements = 1;
  for (hsize_t d : block) elements *= d;
  if (elements == 0) return;  // zero bodies: extend only
  H5::DataSpace file_space = dataset->getSpace();
  file_space.selectHyperslab(H5S_SELECT_SET, block.data(), start.data());
  H5::DataSpace mem_space(static_cast<int>(block.size()), block.data());
  dataset->write(data, memtype, mem_space, file_space);
}

Series create_series(const H5::Group& group, const std::string& name, const H5::DataType& type,
                     const std::vector<hsize_t>& row_shape, hsize_t chunk_rows,
                     const std::string& units, const std::string& description, bool compress) {
  std::vector<hsize_t> dims{0}, maxdims{H5S_UNLIMITED}, chunk{chunk_rows};
  for (hsize_t d : row_shape) {
    dims.push_back(d);
    // a zero-size fixed dimension cannot hold a chunk; make it extendible instead
    maxdims.push_back(d > 0 ? d : H5S_UNLIMITED);
    chunk.push_back(std::max<hsize_t>(d, 1));
  }
  H5::DataSpace space(static_cast<int>(dims.size()), dims.data(), maxdims.data());
  H5::DSetCreatPropList props;
  props.setChunk(static_cast<int>(chunk.size()), chunk.data());
  if (compress) {
    props.setShuffle();
    props.setDeflate(kDeflateLevel);
  }
  Series series;
  series.dataset = std::make_unique<H5::DataSet>(group.createDataSet(name, type, space, props));
  series.row_shape = row_shape;
  write_attr(*series.dataset, "units", units);
  write_attr(*series.dataset, "description", description);
  return series;
}

H5::FileAccPropList unlocked_access() {
  H5::FileAccPropList access;
#if H5_VERSION_GE(1, 10, 7)
  H5Pset_file_locking(access.getId(), false, true);
#endif
  return access;
}

Series open_series(const H5::Group& group, const std::string& name) {
  Series series;
  series.dataset = std::make_unique<H5::DataSet>(group.openDataSet(name));
  const H5::DataSpace space = series.dataset->getSpace();
  std::vector<hsize_t> dims(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(dims.data());
  series.rows = dims.at(0);
  series.row_shape.assign(dims.begin() + 1, dims.end());
  return series;
}

void write_fixed(const H5::Group& group, const std::string& name, const H5::DataType& file_type,
                 const H5::DataType& mem_type, const std::vector<hsize_t>& dims,
                 const void* data, const std::string& units, const std::string& description, bool compress) {
  H5::DataSpace space(static_cast<int>(dims.size()), dims.data());
  hsize_t elements = 1;
  for (hsize_t d : dims) elements *= d;
  H5::DSetCreatPropList props;
  if (compress && elements > 0 && !dims.empty()) {
    std::vector<hsize_t> chunk = dims;
    chunk[0] = std::min<hsize_t>(chunk[0], kFixedChunkRows);
    props.setChunk(static_cast<int>(chunk.size()), chunk.data());
    props.setShuffle();
    props.setDeflate(kDeflateLevel);
  }
  H5::DataSet dataset = group.createDataSet(name, file_type, space, props);
  if (elements > 0) dataset.write(data, mem_type);
  write_attr(dataset, "units", units);
  write_attr(dataset, "description", description);
}

}  // namespace icedem
