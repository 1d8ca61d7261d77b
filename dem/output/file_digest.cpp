#include "dem/output/file_digest.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace icedem {
namespace {

class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new()) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_, EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("OpenSSL: cannot start a SHA-256 digest");
  }
  ~Sha256() { EVP_MD_CTX_free(ctx_); }
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void add(const void* data, std::size_t bytes) {
    if (bytes && EVP_DigestUpdate(ctx_, data, bytes) != 1) throw std::runtime_error("OpenSSL: SHA-256 update failed");
  }
  // with its length first, so that no two sequences of texts run together into the same bytes
  void add_text(const std::string& s) {
    const uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  void add_number(uint64_t n) { add(&n, sizeof n); }

  std::string hex() {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    if (EVP_DigestFinal_ex(ctx_, md, &n) != 1) throw std::runtime_error("OpenSSL: SHA-256 final failed");
    std::string out;
    for (unsigned i = 0; i < n; ++i) out += fmt::format("{:02x}", md[i]);
    return out;
  }

 private:
  EVP_MD_CTX* ctx_;
};

// an HDF5 identifier closed when it goes out of scope
struct Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Id() {
    if (id >= 0) close(id);
  }
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error(fmt::format("HDF5: cannot {}", what));
}

// the type as HDF5 encodes it: class, size, byte order, members
void add_type(Sha256& sha, hid_t type) {
  std::size_t bytes = 0;
  check(H5Tencode(type, nullptr, &bytes), "encode a datatype");
  std::vector<unsigned char> buffer(bytes);
  check(H5Tencode(type, buffer.data(), &bytes), "encode a datatype");
  sha.add_number(bytes);
  sha.add(buffer.data(), bytes);
}

void add_shape(Sha256& sha, hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  check(rank, "read a dataspace");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), "read a dataspace");
  sha.add_number(static_cast<uint64_t>(rank));
  for (hsize_t d : dims) sha.add_number(d);
}

// Values of an attribute or dataset. A variable-length string is read as text; any other type of
// fixed size as its bytes in the file's own type (no conversion, so every bit counts).
// read(memory type, buffer) reads every value
template <typename Read>
void add_values(Sha256& sha, hid_t type, hid_t space, Read&& read) {
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  check(static_cast<herr_t>(count < 0 ? -1 : 0), "count a dataspace's points");
  const htri_t variable = H5Tis_variable_str(type);
  if (variable > 0) {
    Id text{H5Tcopy(H5T_C_S1), H5Tclose};
    check(H5Tset_size(text.id, H5T_VARIABLE), "make a string type");
    check(H5Tset_cset(text.id, H5Tget_cset(type)), "make a string type");  // HDF5 converts no character set
    std::vector<char*> values(static_cast<std::size_t>(count), nullptr);
    check(read(text.id, values.data()), "read strings");
    for (char* v : values) sha.add_text(v ? std::string(v) : std::string());
    H5Dvlen_reclaim(text.id, space, H5P_DEFAULT, values.data());
    return;
  }
  if (H5Tdetect_class(type, H5T_VLEN) > 0) {
    sha.add_text("variable-length values not digested");  // the project writes none
    return;
  }
  const std::size_t size = H5Tget_size(type);
  std::vector<unsigned char> buffer(static_cast<std::size_t>(count) * size);
  if (!buffer.empty()) check(read(type, buffer.data()), "read values");
  sha.add(buffer.data(), buffer.size());
}

struct Walk {
  const std::string& skip_group;      // "/checkpoint"
  const std::string& skip_attribute;  // "digest"
  std::map<std::string, std::unique_ptr<Sha256>> parts;
  std::string error;  // what stopped the walk inside one of HDF5's callbacks

  Sha256& part(const std::string& path) {
    // "/checkpoint/world/bodies" -> "/checkpoint/world"; "/load/surge" -> "/load"
    std::vector<std::string> names;
    std::stringstream in(path);
    for (std::string name; std::getline(in, name, '/');)
      if (!name.empty()) names.push_back(name);
    std::string key = "/";
    if (!names.empty()) key += names[0];
    if (names.size() >= 2 && names[0] == "checkpoint") key += "/" + names[1];
    auto& sha = parts[key];
    if (!sha) sha = std::make_unique<Sha256>();
    return *sha;
  }

  void add_attributes(hid_t object, const std::string& path) {
    struct Context {
      Walk* walk;
      const std::string* path;
    } context{this, &path};
    const herr_t status = H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr,
                      [](hid_t location, const char* name, const H5A_info_t*, void* data) -> herr_t {
                        auto& c = *static_cast<Context*>(data);
                        if (*c.path == c.walk->skip_group && name == c.walk->skip_attribute) return 0;
                        try {  // no exception through HDF5's C frames
                          Sha256& sha = c.walk->part(*c.path);
                          Id attr{H5Aopen(location, name, H5P_DEFAULT), H5Aclose};
                          Id type{H5Aget_type(attr.id), H5Tclose};
                          Id space{H5Aget_space(attr.id), H5Sclose};
                          if (attr.id < 0 || type.id < 0 || space.id < 0) return -1;
                          sha.add_text(std::string("attribute ") + name);
                          add_type(sha, type.id);
                          add_shape(sha, space.id);
                          add_values(sha, type.id, space.id,
                                     [&](hid_t mem, void* buffer) { return H5Aread(attr.id, mem, buffer); });
                        } catch (const std::exception& e) {
                          c.walk->error = e.what() + (" (attribute " + std::string(name) + ")");
                          return -1;
                        }
                        return 0;
                      },
                      &context);
    if (status < 0) throw std::runtime_error(error.empty() ? "HDF5: cannot read attributes" : error);
  }

  void add_dataset(hid_t set, const std::string& path) {
    Sha256& sha = part(path);
    Id type{H5Dget_type(set), H5Tclose};
    Id space{H5Dget_space(set), H5Sclose};
    check(static_cast<herr_t>(type.id < 0 || space.id < 0 ? -1 : 0), "open a dataset");
    add_type(sha, type.id);
    add_shape(sha, space.id);
    const int rank = H5Sget_simple_extent_ndims(space.id);
    if (rank < 1 || H5Tis_variable_str(type.id) > 0 || H5Tdetect_class(type.id, H5T_VLEN) > 0) {
      add_values(sha, type.id, space.id,
                 [&](hid_t mem, void* buffer) { return H5Dread(set, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer); });
      return;
    }
    // by blocks of rows, so that a large dataset needs no more than a few MB at a time
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
    const std::size_t row_bytes =
        std::max<std::size_t>(1, H5Tget_size(type.id) * static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.id)) /
                                     std::max<hsize_t>(1, dims[0]));
    const hsize_t block = std::max<hsize_t>(1, (8u << 20) / row_bytes);
    std::vector<unsigned char> buffer;
    for (hsize_t first = 0; first < dims[0]; first += block) {
      std::vector<hsize_t> start(dims.size(), 0), count = dims;
      start[0] = first;
      count[0] = std::min(block, dims[0] - first);
      Id file_space{H5Scopy(space.id), H5Sclose};
      check(H5Sselect_hyperslab(file_space.id, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
            "select rows");
      Id memory{H5Screate_simple(rank, count.data(), nullptr), H5Sclose};
      buffer.resize(static_cast<std::size_t>(count[0]) * row_bytes);
      check(H5Dread(set, type.id, memory.id, file_space.id, H5P_DEFAULT, buffer.data()), "read a dataset");
      sha.add(buffer.data(), buffer.size());
    }
  }
};

}  // namespace

FileDigest file_digest(const H5::H5File& file, const std::string& skip_group, const std::string& skip_attribute) {
  Walk walk{skip_group, skip_attribute, {}, {}};
  const hid_t root = file.getId();
  walk.part("/");
  walk.add_attributes(root, "/");
  const herr_t status = H5Lvisit(root, H5_INDEX_NAME, H5_ITER_INC,
                 [](hid_t group, const char* name, const H5L_info_t* info, void* data) -> herr_t {
                   Walk& w = *static_cast<Walk*>(data);
                   const std::string path = std::string("/") + name;
                   try {  // no exception through HDF5's C frames
                     Sha256& sha = w.part(path);
                     sha.add_text("link " + path);
                     if (info->type != H5L_TYPE_HARD) {  // a soft or external link: its target
                       std::vector<char> target(info->u.val_size + 1, 0);
                       if (H5Lget_val(group, name, target.data(), target.size(), H5P_DEFAULT) < 0) return -1;
                       sha.add(target.data(), info->u.val_size);
                       return 0;
                     }
                     Id object{H5Oopen(group, name, H5P_DEFAULT), H5Oclose};
                     if (object.id < 0) return -1;
                     w.add_attributes(object.id, path);
                     if (H5Iget_type(object.id) == H5I_DATASET) w.add_dataset(object.id, path);
                   } catch (const std::exception& e) {
                     if (w.error.empty()) w.error = e.what() + (" at " + path);
                     return -1;
                   }
                   return 0;
                 },
                 &walk);
  if (status < 0) throw std::runtime_error(walk.error.empty() ? "HDF5: cannot walk the file" : walk.error);
  FileDigest digest;
  for (auto& [part, sha] : walk.parts) digest[part] = sha->hex();
  return digest;
}

std::string format_digest(const FileDigest& digest) {
  std::string out;
  for (const auto& [part, hex] : digest) out += part + " " + hex + "\n";
  return out;
}

FileDigest parse_digest(const std::string& text) {
  FileDigest digest;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto space = line.find(' ');
    if (space == std::string::npos || space == 0 || line.size() - space - 1 != 64)
      throw std::invalid_argument("not a line of a digest: '" + line + "'");
    digest[line.substr(0, space)] = line.substr(space + 1);
  }
  return digest;
}

std::vector<std::string> digest_differences(const FileDigest& recorded, const FileDigest& now) {
  std::vector<std::string> out;
  for (const auto& [part, hex] : recorded) {
    const auto it = now.find(part);
    if (it == now.end()) out.push_back(part + " (missing)");
    else if (it->second != hex) out.push_back(part);
  }
  for (const auto& [part, hex] : now)
    if (!recorded.count(part)) out.push_back(part + " (added)");
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace icedem
