// The DSMC of the granular column in gravity (gravity_column_dsmc.hpp; docs/theory.md §23.3).
#include "gkt/simulation/gravity_column_dsmc.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/simulation/random_stream.hpp"

namespace gkt {

namespace {

struct Particle {
  double z = 0;
  std::array<double, 3> v{};  ///< v[2] vertical in 3D; v[1] vertical in 2D (v[2] unused, 0)
};

void require(bool ok, const std::string& field, const std::string& allowed, double got) {
  if (!ok) throw std::invalid_argument(field + ": must be " + allowed + ", got " + std::to_string(got));
}

}  // namespace

GravityColumnDsmcProfile run_gravity_column_dsmc(const GravityColumnDsmcParameters& p) {
  require(p.dimension == 2 || p.dimension == 3, "dimension", "2 or 3", p.dimension);
  require(p.alpha > 0 && p.alpha <= 1, "alpha", "in (0, 1]", p.alpha);
  require(std::isfinite(p.particles_per_area) && p.particles_per_area > 0, "particles_per_area", "> 0",
          p.particles_per_area);
  require(std::isfinite(p.floor_temperature) && p.floor_temperature > 0, "floor_temperature", "> 0",
          p.floor_temperature);
  require(std::isfinite(p.lid_height) && p.lid_height > 0, "lid_height", "> 0", p.lid_height);
  require(p.particles >= 100, "particles", ">= 100", p.particles);
  require(std::isfinite(p.cell_height) && p.cell_height > 0 && p.lid_height / p.cell_height >= 2, "cell_height",
          "> 0 and at most lid_height/2", p.cell_height);
  require(std::isfinite(p.time_step) && p.time_step > 0, "time_step", "> 0", p.time_step);
  require(std::isfinite(p.settle_time) && p.settle_time >= 0, "settle_time", ">= 0", p.settle_time);
  require(std::isfinite(p.sample_time) && p.sample_time >= 5 * p.time_step, "sample_time", ">= 5 time_step",
          p.sample_time);

  const int d = p.dimension, up = d - 1;
  const auto cells = static_cast<std::size_t>(p.lid_height / p.cell_height);
  const double height = p.lid_height, dz = height / static_cast<double>(cells), dt = p.time_step;
  const double weight = p.particles_per_area / p.particles;  // real particles per simulated one and unit area
  // Candidate pairs per step and cell: ½ N_c(N_c−1) (W/A) (S_d/2) σ^{d−1} u_max Δt/Δz, S_d the unit
  // sphere's surface (4π, 2π): σ̂ uniform on it, accepted with |g·σ̂|/u_max (rate S_d/2 ⟨|g·σ̂|⟩ = πg, 2g).
  const double half_surface = d == 3 ? 2 * std::numbers::pi : std::numbers::pi;
  const double wall = std::sqrt(p.floor_temperature);
  RandomStream rng(dsmc_run_seed(p.seed, 0));

  std::vector<Particle> gas(static_cast<std::size_t>(p.particles));
  for (auto& a : gas) {  // barometric start at the wall temperature
    a.z = -p.floor_temperature * std::log(1 - rng.uniform());
    if (a.z >= height) a.z = height * rng.uniform();
    for (int k = 0; k < d; ++k) a.v[k] = wall * rng.gaussian();
  }
  std::vector<std::vector<std::size_t>> members(cells);
  std::vector<double> majorant(cells, 5 * wall), remainder(cells, 0);
  std::vector<double> count(cells, 0), energy(cells, 0), vertical(cells, 0), drift(cells, 0), flux(cells, 0);
  std::vector<double> transfer(cells, 0), loss(cells, 0);
  double energy_in = 0, samples = 0;
  const auto settle_steps = static_cast<long>(std::llround(p.settle_time / dt));
  const long steps = settle_steps + static_cast<long>(std::llround(p.sample_time / dt));
  auto cell_of = [&](double z) { return std::min(static_cast<std::size_t>(std::max(z, 0.0) / dz), cells - 1); };

  for (long step = 0; step < steps; ++step) {
    const bool sampling = step >= settle_steps, sample_flux = sampling && (step - settle_steps) % 5 == 0;
    // The kinetic flux is sampled at the middle of each flight (z + w Δt/2 − Δt²/8, w − Δt/2, after
    // a floor hit before then): sampled at its start, n⟨(m/2)V²V_z⟩ would differ from the flight's
    // time average by (Δt/2)[∂_z(n⟨½V²V_z²⟩) + g n⟨V_z² + ½V²⟩], 2.5 % of q at Δt = 0.02 (docs/theory.md §23.3).
    const double half = dt / 2;
    auto add_flux = [&](double z, double w, double horizontal) {
      if (z >= height) z = 2 * height - z, w = -w;  // past the lid: the mirror image
      flux[cell_of(z)] += (horizontal + w * w) / 2 * w;
    };
    auto horizontal_v2 = [&](const Particle& a) {
      double h = 0;
      for (int k = 0; k < d; ++k) h += k == up ? 0 : a.v[k] * a.v[k];
      return h;
    };
    for (auto& a : gas) {  // free flight under gravity, the walls
      const double z0 = a.z, w0 = a.v[up];
      a.z = z0 + w0 * dt - dt * dt / 2;
      a.v[up] = w0 - dt;
      const double hit = a.z < 0 ? std::clamp(w0 + std::sqrt(w0 * w0 + 2 * z0), 0.0, dt) : dt;
      if (sample_flux && hit >= half) add_flux(z0 + w0 * half - half * half / 2, w0 - half, horizontal_v2(a));
      if (a.z < 0) {  // hits the floor at s: z0 + w0 s − s²/2 = 0; re-emitted at the wall temperature
        const double s = hit;
        a.v[up] = w0 - s;
        double before = 0, after = 0;
        for (int k = 0; k < d; ++k) before += a.v[k] * a.v[k];
        for (int k = 0; k < d; ++k) a.v[k] = wall * rng.gaussian();
        a.v[up] = wall * std::sqrt(-2 * std::log(1 - rng.uniform()));  // flux-weighted normal speed
        for (int k = 0; k < d; ++k) after += a.v[k] * a.v[k];
        if (sampling) energy_in += (after - before) / 2;
        const double rest = dt - s, after_hit = half - s;
        if (sample_flux && s < half)
          add_flux(std::max(a.v[up] * after_hit - after_hit * after_hit / 2, 0.0), a.v[up] - after_hit,
                   horizontal_v2(a));
        a.z = std::max(a.v[up] * rest - rest * rest / 2, 0.0);
        a.v[up] -= rest;
      }
      if (a.z >= height) {  // specular lid
        a.z = std::min(2 * height - a.z, std::nextafter(height, 0.0));
        a.v[up] = -a.v[up];
      }
    }
    for (auto& m : members) m.clear();
    for (std::size_t i = 0; i < gas.size(); ++i) members[cell_of(gas[i].z)].push_back(i);
    for (std::size_t c = 0; c < cells; ++c) {  // NTC collisions
      const auto& m = members[c];
      const double nc = static_cast<double>(m.size());
      if (m.size() < 2) continue;
      const double expected = nc * (nc - 1) / 2 * weight * half_surface * majorant[c] * dt / dz + remainder[c];
      const auto candidates = static_cast<long>(expected);
      remainder[c] = expected - static_cast<double>(candidates);
      for (long t = 0; t < candidates; ++t) {
        const std::size_t i = m[rng.below(m.size())], j = m[rng.below(m.size())];
        if (i == j) continue;
        std::array<double, 3> n{};
        if (d == 3) {
          const double ct = 2 * rng.uniform() - 1, phi = 2 * std::numbers::pi * rng.uniform(),
                       st = std::sqrt(1 - ct * ct);
          n = {st * std::cos(phi), st * std::sin(phi), ct};
        } else {
          const double phi = 2 * std::numbers::pi * rng.uniform();
          n = {std::cos(phi), std::sin(phi), 0};
        }
        double gn = 0;
        for (int k = 0; k < d; ++k) gn += (gas[i].v[k] - gas[j].v[k]) * n[k];
        majorant[c] = std::max(majorant[c], std::abs(gn));
        if (std::abs(gn) < rng.uniform() * majorant[c]) continue;
        const double f = (1 + p.alpha) / 2 * gn;
        if (sampling) {  // cell transfer [alexander1998cell]: ½(δE_j − δE_i) = f (v_i + v_j)·n̂/2 moved by z_j − z_i
          double sn = 0;
          for (int k = 0; k < d; ++k) sn += (gas[i].v[k] + gas[j].v[k]) * n[k];
          transfer[c] += f * sn / 2 * (gas[j].z - gas[i].z);
          loss[c] += f * (gn - f);  // −(δE_i + δE_j)
        }
        for (int k = 0; k < d; ++k) {
          gas[i].v[k] -= f * n[k];
          gas[j].v[k] += f * n[k];
        }
      }
    }
    if (sampling && (step - settle_steps) % 5 == 0) {
      samples += 1;
      for (const auto& a : gas) {
        const std::size_t c = cell_of(a.z);
        double v2 = 0;
        for (int k = 0; k < d; ++k) v2 += a.v[k] * a.v[k];
        count[c] += 1;
        energy[c] += v2;
        vertical[c] += a.v[up] * a.v[up];
        drift[c] += a.v[up];
      }
    }
  }
  GravityColumnDsmcProfile out;
  const double sampled_time = static_cast<double>(steps - settle_steps) * dt;
  out.floor_heat_flux = energy_in * weight / sampled_time;
  for (std::size_t c = 0; c < cells; ++c) {
    out.z.push_back((static_cast<double>(c) + 0.5) * dz);
    out.number_density.push_back(count[c] / samples * weight / dz);
    const double u = count[c] > 0 ? drift[c] / count[c] : 0;
    const double empty = std::numeric_limits<double>::quiet_NaN();  // no particle ever sampled there
    out.temperature.push_back(count[c] > 0 ? (energy[c] / count[c] - u * u) / d : empty);
    out.vertical_temperature.push_back(count[c] > 0 ? vertical[c] / count[c] - u * u : empty);
    out.kinetic_heat_flux.push_back(flux[c] / samples * weight / dz);
    out.collisional_heat_flux.push_back(transfer[c] * weight / (sampled_time * dz));
    out.heat_flux.push_back(out.kinetic_heat_flux.back() + out.collisional_heat_flux.back());
    out.dissipation.push_back(loss[c] * weight / (sampled_time * dz));
  }
  return out;
}

}  // namespace gkt
