#include "catalogue/builtin.hpp"

#include "catalogue/fischer.hpp"
#include "catalogue/mc_round.hpp"
#include "catalogue/path_reservation.hpp"
#include "catalogue/path_reservation_picture.hpp"
#include "catalogue/token_ring.hpp"
#include "catalogue/vlayer_mc.hpp"
#include "catalogue/vlayer_mc_picture.hpp"
#include "catalogue/vn_emulation.hpp"
#include "catalogue/vn_layer.hpp"

namespace catalogue {

const Catalogue& builtin_models() {
  static const Catalogue models = [] {
    Catalogue c;
    ModelDefinition vlayer_mc = vlayer_mc_definition();
    vlayer_mc.picture = write_vlayer_mc_picture;
    ModelDefinition path_reservation = path_reservation_definition();
    path_reservation.picture = write_path_reservation_picture;
    c.add(token_ring_definition())
        .add(fischer_definition())
        .add(mc_round_definition())
        .add(std::move(vlayer_mc))
        .add(vn_layer_definition())
        .add(vn_emulation_definition())
        .add(std::move(path_reservation));
    return c;
  }();
  return models;
}

} // namespace catalogue
