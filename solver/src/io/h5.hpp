#pragma once
// A small RAII layer over the HDF5 C API: just what the result files need.
// Object timestamps are off so identical runs give byte-identical files.
#include <hdf5.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cellsim::h5 {

// Owns one hid_t and closes it with the matching H5*close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close);
  Handle(Handle&& o) noexcept;
  Handle& operator=(Handle&& o) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle();
  hid_t id() const { return id_; }
  void close();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

// Both throw FileError with what HDF5 and the system said (and, for a lock HDF5 cannot take, the
// HDF5_USE_FILE_LOCKING=FALSE hint); create_file truncates. A file that is not HDF5 at all is an
// InputError.
Handle create_file(const std::string& path);
Handle open_file_readonly(const std::string& path);
// HDF5's own account of the last failure on this thread: its error stack, outermost first.
std::string last_error();
Handle create_group(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& path);

// Datasets: row-major, dims = {rows} or {rows, cols}.
void write(hid_t parent, const std::string& name, const std::vector<double>& data,
           const std::vector<hsize_t>& dims);
void write(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data,
           const std::vector<hsize_t>& dims);
void write(hid_t parent, const std::string& name, const std::vector<std::int32_t>& data,
           const std::vector<hsize_t>& dims);
std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* dims = nullptr);
std::vector<std::int32_t> read_ints(hid_t parent, const std::string& name, std::vector<hsize_t>* dims = nullptr);

// Attributes on a group or dataset (parent) or on an object by path below it.
void set_attr(hid_t obj, const std::string& name, const std::string& value);
void set_attr(hid_t obj, const std::string& name, double value);
void set_attr(hid_t obj, const std::string& name, std::int64_t value);
std::string get_attr_string(hid_t obj, const std::string& name);
double get_attr_double(hid_t obj, const std::string& name);
std::int64_t get_attr_int(hid_t obj, const std::string& name);
bool has_attr(hid_t obj, const std::string& name);
void set_dataset_attr(hid_t parent, const std::string& dataset, const std::string& name, const std::string& value);

}  // namespace cellsim::h5
