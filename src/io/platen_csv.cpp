#include "biphasic/io/platen_csv.hpp"

#include <stdexcept>

#include "biphasic/io/atomic_file.hpp"

namespace biphasic {

PlatenCsv::PlatenCsv(const std::string& path, bool append) : path_(path) {
  out_.open(path, append ? std::ios::out | std::ios::app : std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot open " + path + " for writing");
  out_.precision(17);
  if (!append) out_ << "t,platen,displacement,force\n";
  flush_checked(out_, path_);
}

void PlatenCsv::write(double t, const std::string& platen, double displacement, double force) {
  out_ << t << ',' << platen << ',' << displacement << ',' << force << '\n';
  flush_checked(out_, path_);
}

}  // namespace biphasic
