#include "biphasic/io/reaction_csv.hpp"

#include <stdexcept>

#include "biphasic/io/atomic_file.hpp"

namespace biphasic {

ReactionCsv::ReactionCsv(const std::string& path, bool append) : path_(path) {
  out_.open(path, append ? std::ios::out | std::ios::app : std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot open " + path + " for writing");
  out_.precision(17);
  if (!append) out_ << "t,boundary,Fx,Fy,Fz\n";
  flush_checked(out_, path_);
}

void ReactionCsv::write(double t, const std::vector<std::string>& names,
                        const std::vector<std::array<double, 3>>& forces) {
  for (std::size_t b = 0; b < names.size(); ++b)
    out_ << t << ',' << names[b] << ',' << forces[b][0] << ',' << forces[b][1] << ','
         << forces[b][2] << '\n';
  flush_checked(out_, path_);
}

}  // namespace biphasic
