#include "io/h5.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/errors.hpp"

namespace cellsim::h5 {
namespace {

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: " + what + " failed (" + last_error() + ")");
  return id;
}

void check(herr_t status, const std::string& what, int) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed (" + last_error() + ")");
}

int collect_message(unsigned, const H5E_error2_t* e, void* out) {
  auto& text = *static_cast<std::string*>(out);
  if (!e->desc || !*e->desc) return 0;
  std::string line(e->desc);
  for (char& c : line)
    if (c == '\n') c = ' ';  // one line: some HDF5 descriptions carry a newline
  text += (text.empty() ? "" : "; ") + line;
  return 0;
}

// A FileError for a file HDF5 could not create or open: what HDF5 said, what the system said, and
// the locking hint when HDF5 could not lock it (file systems such as some NFS mounts cannot).
[[noreturn]] void file_error(const std::string& action, const std::string& path, int saved_errno) {
  const std::string hdf5 = last_error();
  std::string msg = "cannot " + action + " HDF5 file '" + path + "': " + (hdf5.empty() ? "HDF5 gave no reason" : hdf5);
  if (saved_errno != 0) msg += " (system: " + std::string(std::strerror(saved_errno)) + ")";
  if (hdf5.find("lock") != std::string::npos)
    msg += "; another program may have the file open, or this file system cannot lock files: then run with "
           "HDF5_USE_FILE_LOCKING=FALSE in the environment";
  throw FileError(msg);
}

// Object-creation property lists with timestamps off: identical runs, identical files
// (docs/output-reference.md, "How a file is written").
Handle untimed(hid_t cls) {
  Handle plist(check(H5Pcreate(cls), "H5Pcreate"), H5Pclose);
  check(H5Pset_obj_track_times(plist.id(), false), "H5Pset_obj_track_times", 0);
  return plist;
}

template <class T>
void write_typed(hid_t parent, const std::string& name, const std::vector<T>& data,
                 const std::vector<hsize_t>& dims, hid_t file_type, hid_t mem_type) {
  hsize_t n = 1;
  for (auto d : dims) n *= d;
  if (n != data.size()) throw std::runtime_error("HDF5: dataset " + name + " has a size mismatch");
  Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), "H5Screate"),
               H5Sclose);
  Handle dcpl = untimed(H5P_DATASET_CREATE);
  if (n > 0) {  // one chunk with a Fletcher-32 checksum: a bit changed on disk fails the read (issue 51)
    check(H5Pset_chunk(dcpl.id(), static_cast<int>(dims.size()), dims.data()), "H5Pset_chunk", 0);
    check(H5Pset_fletcher32(dcpl.id()), "H5Pset_fletcher32", 0);
  }
  Handle set(check(H5Dcreate2(parent, name.c_str(), file_type, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                   "create dataset " + name),
             H5Dclose);
  if (n > 0) check(H5Dwrite(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write " + name, 0);
}

template <class T>
std::vector<T> read_typed(hid_t parent, const std::string& name, std::vector<hsize_t>* dims, hid_t mem_type) {
  Handle set(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle space(check(H5Dget_space(set.id()), "H5Dget_space"), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id(), d.data(), nullptr);
  hsize_t n = 1;
  for (auto x : d) n *= x;
  std::vector<T> out(n);
  if (n > 0) check(H5Dread(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name, 0);
  if (dims) *dims = d;
  return out;
}

Handle open_attr(hid_t obj, const std::string& name) {
  return Handle(check(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
}

void write_scalar_attr(hid_t obj, const std::string& name, hid_t type, const void* value) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
  Handle attr(check(H5Acreate2(obj, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name),
              H5Aclose);
  check(H5Awrite(attr.id(), type, value), "write attribute " + name, 0);
}

}  // namespace

Handle::Handle(hid_t id, Closer close) : id_(id), close_(close) {}
Handle::Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = H5I_INVALID_HID; }
Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    close();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}
Handle::~Handle() { close(); }
void Handle::close() {
  if (id_ >= 0 && close_) close_(id_);
  id_ = H5I_INVALID_HID;
}

std::string last_error() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_message, &text);
  return text;
}

Handle create_file(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by us, not printed by HDF5
  Handle fcpl = untimed(H5P_FILE_CREATE);  // the root group's header too (the 1.8 format keeps its times)
  // The HDF5 1.10 file format: its superblock, object headers (the attributes, and a one-chunk dataset's
  // chunk address, size and filter mask) and link storage carry checksums, so a changed byte of the
  // file's structure fails to open or read, as the datasets' own do. (The 1.8 format indexed chunks in
  // B-trees without checksums: the fuzzer found a flip there read as another dataset's values.)
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate"), H5Pclose);
  check(H5Pset_libver_bounds(fapl.id(), H5F_LIBVER_V110, H5F_LIBVER_LATEST), "H5Pset_libver_bounds", 0);
  errno = 0;
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), fapl.id()), H5Fclose);
  if (file.id() < 0) file_error("create", path, errno);
  return file;
}

Handle open_file_readonly(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path.c_str()) == 0) throw InputError("'" + path + "' is not an HDF5 file");  // content, not place
  errno = 0;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.id() < 0) file_error("open", path, errno);
  return file;
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle gcpl = untimed(H5P_GROUP_CREATE);
  return Handle(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT), "create group " + name),
                H5Gclose);
}

Handle open_group(hid_t parent, const std::string& name) {
  return Handle(check(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), "open group " + name), H5Gclose);
}

bool exists(hid_t parent, const std::string& path) {
  // Check each component: H5Lexists fails on a missing intermediate group.
  std::size_t pos = 0;
  while (true) {
    const std::size_t next = path.find('/', pos);
    const std::string prefix = path.substr(0, next);
    const htri_t found = prefix.empty() ? 1 : H5Lexists(parent, prefix.c_str(), H5P_DEFAULT);
    if (found < 0) throw std::runtime_error("HDF5: looking for " + prefix + " failed (" + last_error() + ")");
    if (found == 0) return false;
    if (next == std::string::npos) return true;
    pos = next + 1;
  }
}

void write(hid_t parent, const std::string& name, const std::vector<double>& data, const std::vector<hsize_t>& dims) {
  write_typed(parent, name, data, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}
void write(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data,
           const std::vector<hsize_t>& dims) {
  write_typed(parent, name, data, dims, H5T_STD_I64LE, H5T_NATIVE_INT64);
}
void write(hid_t parent, const std::string& name, const std::vector<std::int32_t>& data,
           const std::vector<hsize_t>& dims) {
  write_typed(parent, name, data, dims, H5T_STD_I32LE, H5T_NATIVE_INT32);
}
std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* dims) {
  return read_typed<double>(parent, name, dims, H5T_NATIVE_DOUBLE);
}
std::vector<std::int32_t> read_ints(hid_t parent, const std::string& name, std::vector<hsize_t>* dims) {
  return read_typed<std::int32_t>(parent, name, dims, H5T_NATIVE_INT32);
}

void set_attr(hid_t obj, const std::string& name, const std::string& value) {
  Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
  H5Tset_size(type.id(), value.empty() ? 1 : value.size());
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  write_scalar_attr(obj, name, type.id(), value.empty() ? "" : value.data());
}
void set_attr(hid_t obj, const std::string& name, double value) {
  write_scalar_attr(obj, name, H5T_NATIVE_DOUBLE, &value);
}
void set_attr(hid_t obj, const std::string& name, std::int64_t value) {
  write_scalar_attr(obj, name, H5T_NATIVE_INT64, &value);
}

std::string get_attr_string(hid_t obj, const std::string& name) {
  Handle attr = open_attr(obj, name);
  Handle type(check(H5Aget_type(attr.id()), "H5Aget_type"), H5Tclose);
  if (H5Tis_variable_str(type.id()) > 0) throw std::runtime_error("HDF5: variable-length string attribute " + name);
  std::string out(H5Tget_size(type.id()), '\0');
  check(H5Aread(attr.id(), type.id(), out.data()), "read attribute " + name, 0);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}
double get_attr_double(hid_t obj, const std::string& name) {
  Handle attr = open_attr(obj, name);
  double v = 0;
  check(H5Aread(attr.id(), H5T_NATIVE_DOUBLE, &v), "read attribute " + name, 0);
  return v;
}
std::int64_t get_attr_int(hid_t obj, const std::string& name) {
  Handle attr = open_attr(obj, name);
  std::int64_t v = 0;
  check(H5Aread(attr.id(), H5T_NATIVE_INT64, &v), "read attribute " + name, 0);
  return v;
}
bool has_attr(hid_t obj, const std::string& name) {  // an error (a header that fails its checksum) is not "no"
  const htri_t found = H5Aexists(obj, name.c_str());
  if (found < 0) throw std::runtime_error("HDF5: looking for attribute " + name + " failed (" + last_error() + ")");
  return found > 0;
}

void set_dataset_attr(hid_t parent, const std::string& dataset, const std::string& name, const std::string& value) {
  Handle set(check(H5Dopen2(parent, dataset.c_str(), H5P_DEFAULT), "open dataset " + dataset), H5Dclose);
  set_attr(set.id(), name, value);
}

}  // namespace cellsim::h5
