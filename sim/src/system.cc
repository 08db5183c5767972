#include "system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>

#include <Eigen/Sparse>

#include "composites.h"
#include "highlift/core/error.h"

namespace highlift::sim::detail {

double FixedAngle(const Element& element);  // elements.cc

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void Unite(int i, int j) { parent[Find(i)] = Find(j); }
};

std::string Join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

// Minimum-norm solution of E x = d (normal equations with a tiny regularization, sparse).
Eigen::VectorXd MinimumNorm(const std::vector<Element::InitialEquation>& rows,
                            const std::vector<int>& unknown, const std::vector<double>& known,
                            int n_unknown, Eigen::VectorXd& d) {
  const int m = static_cast<int>(rows.size());
  d.resize(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n_unknown);
  if (m == 0 || n_unknown == 0) {
    for (int i = 0; i < m; ++i) {
      double r = rows[i].value;
      for (auto [node, coef] : rows[i].row) r -= coef * known[node];
      d[i] = r;
    }
    return x;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < m; ++i) {
    double r = rows[i].value;
    for (auto [node, coef] : rows[i].row) {
      if (unknown[node] >= 0) triplets.emplace_back(i, unknown[node], coef);
      else r -= coef * known[node];
    }
    d[i] = r;
  }
  Eigen::SparseMatrix<double> E(m, n_unknown);
  E.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseMatrix<double> EEt = E * E.transpose();
  double scale = 0.0;
  for (int k = 0; k < EEt.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(EEt, k); it; ++it)
      scale = std::max(scale, std::abs(it.value()));
  Eigen::SparseMatrix<double> I(m, m);
  I.setIdentity();
  EEt += I * (1e-13 * std::max(scale, 1.0));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(EEt);
  if (ldlt.info() != Eigen::Success) return x;
  // Iterative refinement removes the bias of the regularization (long chains of relative
  // initial angles make E*E^T ill-conditioned).
  x.setZero();
  for (int pass = 0; pass < 5; ++pass) {
    const Eigen::VectorXd r = d - E * x;
    if (r.norm() <= 1e-14 * (1.0 + d.norm())) break;
    x += E.transpose() * ldlt.solve(r);
  }
  return x;
}

}  // namespace

System::System(const Network& original) {
  // Composite types become their parts.
  const Network network = FlattenComposites(original);
  // Elements.
  std::map<std::string, int> element_index;
  for (const auto& ne : network.elements()) {
    auto el = MakeElement(ne);
    el->index = static_cast<int>(elements_.size());
    element_index[ne.id] = el->index;
    elements_.push_back(std::move(el));
  }
  // Signal output slots.
  std::map<std::string, int> output_slot;  // "element.port" -> slot
  std::vector<int> slot_owner;             // slot -> element
  for (auto& el : elements_) {
    const auto outputs = el->SignalOutputs();
    if (outputs.empty()) continue;
    el->signal_offset = static_cast<int>(slot_owner.size());
    for (const auto& o : outputs) {
      output_slot[el->id + "." + o] = static_cast<int>(slot_owner.size());
      slot_owner.push_back(el->index);
    }
  }
  n_signal_slots_ = static_cast<int>(slot_owner.size());
  BuildHydraulicNodes(network);
  // Flange ports and their union.
  std::map<std::string, int> port_index;
  std::vector<std::string> port_name;
  std::vector<bool> port_is_support;
  for (const auto& el : elements_)
    for (const auto& f : el->Flanges()) {
      port_index[el->id + "." + f] = static_cast<int>(port_name.size());
      port_name.push_back(el->id + "." + f);
      port_is_support.push_back(f == "support");
    }
  UnionFind ports(static_cast<int>(port_name.size()));
  std::vector<int> degree(port_name.size(), 0);
  for (const auto& el : elements_)
    for (const auto& group : el->RigidFlanges())
      for (std::size_t k = 1; k < group.size(); ++k)
        ports.Unite(port_index.at(el->id + "." + group[0]), port_index.at(el->id + "." + group[k]));
  // Signal connections: input port -> source element.
  std::map<std::string, int> signal_source;
  for (const auto& c : network.connections()) {
    const std::string a = c.a.ToString(), b = c.b.ToString();
    if (std::binary_search(hydraulic_ports_.begin(), hydraulic_ports_.end(), a) ||
        std::binary_search(hydraulic_ports_.begin(), hydraulic_ports_.end(), b))
      continue;  // BuildHydraulicNodes
    auto ia = port_index.find(a), ib = port_index.find(b);
    if (ia != port_index.end() && ib != port_index.end()) {
      ports.Unite(ia->second, ib->second);
      ++degree[ia->second];
      ++degree[ib->second];
      continue;
    }
    if (ia != port_index.end() || ib != port_index.end())
      throw InputError("connection " + a + " - " + b +
                       ": a flange can only be connected to a flange; connect signal ports "
                       "(y, u, tau, f_normalized, w_ref) to each other");
    const PortRef* out = nullptr;
    const PortRef* in = nullptr;
    const bool a_out = output_slot.count(a) > 0, b_out = output_slot.count(b) > 0;
    if (a_out && !b_out) out = &c.a, in = &c.b;
    else if (b_out && !a_out) out = &c.b, in = &c.a;
    if (out == nullptr)
      throw InputError("connection " + a + " - " + b +
                       ": a signal connection joins one output (such as 'y') to one input");
    const std::string key = in->ToString();
    if (signal_source.count(key))
      throw InputError("signal input '" + key + "' is connected twice; connect it to one output");
    signal_source[key] = output_slot.at(out->ToString());
  }
  // Nodes.
  std::map<int, int> root_to_node;
  std::vector<int> port_node(port_name.size());
  std::vector<int> root_size(port_name.size(), 0);
  for (std::size_t p = 0; p < port_name.size(); ++p) ++root_size[ports.Find(static_cast<int>(p))];
  for (std::size_t p = 0; p < port_name.size(); ++p) {
    const int r = ports.Find(static_cast<int>(p));
    auto it = root_to_node.find(r);
    if (it == root_to_node.end()) {
      it = root_to_node.emplace(r, static_cast<int>(nodes_.size())).first;
      Node n;
      n.name = port_name[p];
      nodes_.push_back(n);
    }
    port_node[p] = it->second;
    // An unconnected support is the grounded housing (MSL useSupport=false).
    if (port_is_support[p] && root_size[r] == 1 && degree[p] == 0) nodes_[it->second].ground = true;
  }
  for (const auto& el : elements_)
    if (el->type == "Fixed") {
      Node& n = nodes_[port_node[port_index.at(el->id + ".flange")]];
      n.ground = true;
      n.phi0 = FixedAngle(*el);
      n.name = el->id + ".flange";
    }
  // Bind ports.
  for (auto& el : elements_) {
    auto node_of = [&](const std::string& port) { return port_node[port_index.at(el->id + "." + port)]; };
    auto signal_of = [&](const std::string& port) {
      auto it = signal_source.find(el->id + "." + port);
      if (it == signal_source.end())
        throw InputError("element '" + el->id + "' (" + el->type + "): signal input '" + port +
                         "' is not connected; connect it to the output 'y' of a signal source "
                         "(Constant, Step, Sine, ...)");
      return it->second;
    };
    el->Bind(node_of, signal_of);
    el->AddInertia(nodes_);
  }
  // Signal evaluation order (inputs first).
  {
    std::vector<int> state(elements_.size(), 0);
    std::function<void(int)> visit = [&](int i) {
      if (state[i] == 2) return;
      if (state[i] == 1)
        throw InputError("signal blocks form an algebraic loop through '" + elements_[i]->id +
                         "'; break the loop");
      state[i] = 1;
      for (const auto& in : elements_[i]->SignalInputs()) {
        auto it = signal_source.find(elements_[i]->id + "." + in);
        if (it != signal_source.end()) visit(slot_owner[it->second]);
      }
      state[i] = 2;
      if (elements_[i]->signal_offset >= 0) signal_order_.push_back(i);
    };
    for (std::size_t i = 0; i < elements_.size(); ++i)
      if (elements_[i]->signal_offset >= 0) visit(static_cast<int>(i));
  }
  // States: node angle and speed at first use, then the element's own states.
  auto assign_node = [&](int n) {
    if (n < 0 || nodes_[n].ground || nodes_[n].s_phi >= 0) return;
    nodes_[n].s_phi = n_states_++;
    nodes_[n].s_w = n_states_++;
    state_names_.push_back(nodes_[n].name + ".phi");
    state_names_.push_back(nodes_[n].name + ".w");
  };
  auto assign_hydraulic = [&](int n) {
    if (hnodes_[n].fixed || hnodes_[n].s_p >= 0) return;
    hnodes_[n].s_p = n_states_++;
    state_names_.push_back(hnodes_[n].name + ".p");
  };
  for (auto& el : elements_) {
    for (int n : el->Nodes()) assign_node(n);
    for (int n : el->HydraulicNodes()) assign_hydraulic(n);
    el->state_offset = n_states_;
    n_states_ += el->NumStates();
    for (const auto& s : el->StateNames()) state_names_.push_back(s);
    el->root_offset = n_roots_;
    n_roots_ += el->NumRoots();
  }
  for (std::size_t n = 0; n < nodes_.size(); ++n) assign_node(static_cast<int>(n));
  for (std::size_t n = 0; n < hnodes_.size(); ++n) assign_hydraulic(static_cast<int>(n));
  // Nodes whose acceleration nothing determines.
  std::vector<bool> coupled(nodes_.size(), false);
  for (const auto& el : elements_)
    for (int n : el->CoupledNodes()) coupled[n] = true;
  for (const auto& n : nodes_)
    if (!n.ground && n.J <= 0 && !coupled[&n - nodes_.data()])
      throw InputError("flange '" + n.name +
                       "' has no inertia and no kinematic coupling, so its acceleration is "
                       "undetermined; connect an Inertia there (a small one suffices) or fix it");
  // Outputs.
  for (const auto& el : elements_) {
    output_offset_.push_back(static_cast<int>(output_names_.size()));
    for (const auto& o : el->OutputNames()) output_names_.push_back(el->id + "." + o);
  }
  // Bandwidth: every element's footprint, widened over groups of coupled nodes.
  {
    UnionFind groups(static_cast<int>(nodes_.size()));
    for (const auto& el : elements_) {
      int first = -1;
      for (int n : el->CoupledNodes()) {
        if (nodes_[n].ground) continue;
        if (first < 0) first = n;
        else groups.Unite(first, n);
      }
    }
    std::vector<int> lo(nodes_.size(), std::numeric_limits<int>::max()), hi(nodes_.size(), -1);
    for (const auto& el : elements_) {
      int emin = std::numeric_limits<int>::max(), emax = -1;
      // Node angles are pure integrators (phi' = w, read by no law): only the speeds count.
      for (int n : el->Nodes())
        if (!nodes_[n].ground) {
          emin = std::min(emin, nodes_[n].s_w);
          emax = std::max(emax, nodes_[n].s_w);
        }
      for (int n : el->HydraulicNodes())
        if (hnodes_[n].s_p >= 0) {
          emin = std::min(emin, hnodes_[n].s_p);
          emax = std::max(emax, hnodes_[n].s_p);
        }
      if (el->NumStates() > 0) {
        emin = std::min(emin, el->state_offset);
        emax = std::max(emax, el->state_offset + el->NumStates() - 1);
      }
      if (emax < 0) continue;
      bandwidth_ = std::max(bandwidth_, emax - emin);
      for (int n : el->Nodes())
        if (!nodes_[n].ground) {
          const int r = groups.Find(n);
          lo[r] = std::min(lo[r], emin);
          hi[r] = std::max(hi[r], emax);
        }
    }
    for (std::size_t r = 0; r < nodes_.size(); ++r)
      if (hi[r] >= 0) bandwidth_ = std::max(bandwidth_, hi[r] - lo[r]);
    bandwidth_ = std::max(bandwidth_, 1);  // phi' = w within each node's pair
  }
  // Workspace.
  eval_.phi.assign(nodes_.size(), 0.0);
  eval_.w.assign(nodes_.size(), 0.0);
  eval_.acc.assign(nodes_.size(), 0.0);
  eval_.force.assign(nodes_.size(), 0.0);
  eval_.signal.assign(n_signal_slots_, 0.0);
  eval_.p.assign(hnodes_.size(), 0.0);
  eval_.q.assign(hnodes_.size(), 0.0);
  eval_.cap.assign(hnodes_.size(), 0.0);
  parent_.resize(nodes_.size());
  local_.assign(nodes_.size(), -1);
}

std::vector<double> System::InitialState(double t0) {
  t_segment_ = t0;
  eval_.t = t0;
  eval_.t_segment = t0;
  eval_.initial = true;
  EvaluateSignals();
  std::vector<Element::InitialEquation> position, speed, holonomic;
  std::vector<int> position_owner, speed_owner, holonomic_owner;
  for (const auto& el : elements_) {
    el->InitialEquations(position, speed);
    el->HolonomicRows(holonomic);
    position_owner.resize(position.size(), el->index);
    speed_owner.resize(speed.size(), el->index);
    holonomic_owner.resize(holonomic.size(), el->index);
  }
  std::vector<int> unknown(nodes_.size(), -1);
  std::vector<double> known_phi(nodes_.size(), 0.0), known_w(nodes_.size(), 0.0);
  int n_unknown = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].ground) known_phi[n] = nodes_[n].phi0;
    else unknown[n] = n_unknown++;
  }
  auto solve = [&](std::vector<Element::InitialEquation> rows, std::vector<int> owner,
                   const std::vector<double>& known, const char* what) {
    for (std::size_t k = 0; k < holonomic.size(); ++k) {
      rows.push_back(holonomic[k]);
      owner.push_back(holonomic_owner[k]);
    }
    Eigen::VectorXd d;
    Eigen::VectorXd x = MinimumNorm(rows, unknown, known, n_unknown, d);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      double r = -d[static_cast<int>(i)], scale = std::abs(d[static_cast<int>(i)]);
      for (auto [node, coef] : rows[i].row)
        if (unknown[node] >= 0) {
          r += coef * x[unknown[node]];
          scale += std::abs(coef * x[unknown[node]]);
        }
      if (std::abs(r) > 1e-8 * (1.0 + scale)) {
        const Element& el = *elements_[owner[i]];
        throw InputError("element '" + el.id + "' (" + el.type + "): the initial " + what +
                         " contradict the other initial values or the kinematic constraints "
                         "(residual " + std::to_string(r) +
                         "); give fewer initial values or make them consistent");
      }
    }
    return x;
  };
  Eigen::VectorXd phi = solve(position, position_owner, known_phi, "angles");
  Eigen::VectorXd w = solve(speed, speed_owner, known_w, "speeds");
  std::vector<double> y(n_states_, 0.0);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n].ground) continue;
    y[nodes_[n].s_phi] = phi[unknown[n]];
    y[nodes_[n].s_w] = w[unknown[n]];
    eval_.phi[n] = phi[unknown[n]];
    eval_.w[n] = w[unknown[n]];
  }
  for (const auto& h : hnodes_)
    if (h.s_p >= 0) {
      y[h.s_p] = std::isnan(h.p_start) ? 1e5 : h.p_start;
      eval_.p[&h - hnodes_.data()] = y[h.s_p];
    } else {
      eval_.p[&h - hnodes_.data()] = h.p_fixed;
    }
  for (const auto& el : elements_) el->InitStates(eval_, y.data());
  return y;
}

void System::EvaluateSignals() {
  for (int i : signal_order_) elements_[i]->Signals(eval_, &eval_.signal[elements_[i]->signal_offset]);
}

bool System::Evaluate(double t, const double* y, double* ydot) {
  Eval& e = eval_;
  e.t = t;
  e.t_segment = t_segment_;
  e.y = y;
  e.ydot = ydot;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Node& node = nodes_[n];
    if (node.ground) {
      e.phi[n] = node.phi0;
      e.w[n] = 0.0;
    } else {
      e.phi[n] = y[node.s_phi];
      e.w[n] = y[node.s_w];
    }
    e.force[n] = 0.0;
    e.acc[n] = 0.0;
  }
  for (std::size_t n = 0; n < hnodes_.size(); ++n) {
    e.p[n] = hnodes_[n].fixed ? hnodes_[n].p_fixed : y[hnodes_[n].s_p];
    e.q[n] = 0.0;
    e.cap[n] = 0.0;
  }
  EvaluateSignals();
  e.n_constraints = 0;
  for (auto& el : elements_) el->Forces(e);
  for (auto& el : elements_) el->Constraints(e);
  if (!Solve()) return false;
  for (auto& el : elements_) el->AfterSolve(e);
  if (ydot != nullptr) {
    for (const Node& node : nodes_) {
      if (node.ground) continue;
      ydot[node.s_phi] = y[node.s_w];
      ydot[node.s_w] = e.acc[&node - nodes_.data()];
    }
    for (auto& el : elements_) el->Derivatives(e);
    if (!hnodes_.empty() && !HydraulicDerivatives(ydot)) return false;
  }
  return true;
}

bool System::Solve() {
  Eval& e = eval_;
  const int n_nodes = static_cast<int>(nodes_.size());
  if (e.n_constraints == 0) {
    for (int n = 0; n < n_nodes; ++n)
      if (!nodes_[n].ground) e.acc[n] = e.force[n] / nodes_[n].J;
    return true;
  }
  // Groups of nodes coupled by the active constraints (union-find on reused buffers).
  in_constraint_.assign(n_nodes, 0);
  auto find = [&](int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  };
  for (int k = 0; k < e.n_constraints; ++k) {
    int first = -1;
    auto touch = [&](int n) {
      if (nodes_[n].ground) return;
      if (!in_constraint_[n]) {
        in_constraint_[n] = 1;
        parent_[n] = n;
      }
      if (first < 0) first = n;
      else parent_[find(n)] = find(first);
    };
    for (auto [n, c] : e.constraints[k].row) touch(n);
    for (auto [n, c] : e.constraints[k].column) touch(n);
  }
  n_groups_ = 0;
  group_of_root_.assign(n_nodes, -1);
  auto group = [&](int root) {
    if (group_of_root_[root] < 0) {
      group_of_root_[root] = n_groups_;
      if (static_cast<int>(group_nodes_.size()) <= n_groups_) {
        group_nodes_.emplace_back();
        group_rows_.emplace_back();
      }
      group_nodes_[n_groups_].clear();
      group_rows_[n_groups_].clear();
      ++n_groups_;
    }
    return group_of_root_[root];
  };
  for (int n = 0; n < n_nodes; ++n) {
    if (nodes_[n].ground) continue;
    if (!in_constraint_[n]) {
      e.acc[n] = e.force[n] / nodes_[n].J;
      continue;
    }
    group_nodes_[group(find(n))].push_back(n);
  }
  for (int k = 0; k < e.n_constraints; ++k) {
    int any = -1;
    for (auto [n, c] : e.constraints[k].row)
      if (!nodes_[n].ground) any = n;
    for (auto [n, c] : e.constraints[k].column)
      if (!nodes_[n].ground) any = n;
    if (any < 0) {
      // Constraint between ground nodes only: its torque is undetermined; take 0.
      e.constraints[k].lambda = 0.0;
      continue;
    }
    group_rows_[group(find(any))].push_back(k);
  }
  for (int g = 0; g < n_groups_; ++g) {
    const auto& gn = group_nodes_[g];
    const auto& gk = group_rows_[g];
    const int nn = static_cast<int>(gn.size()), m = static_cast<int>(gk.size());
    const int size = nn + m;
    for (int i = 0; i < nn; ++i) local_[gn[i]] = i;
    A_.setZero(size, size);
    rhs_.setZero(size);
    for (int i = 0; i < nn; ++i) {
      A_(i, i) = nodes_[gn[i]].J;
      rhs_[i] = e.force[gn[i]];
    }
    for (int j = 0; j < m; ++j) {
      const Constraint& c = e.constraints[gk[j]];
      for (auto [n, coef] : c.column)
        if (!nodes_[n].ground) A_(local_[n], nn + j) -= coef;
      for (auto [n, coef] : c.row)
        if (!nodes_[n].ground) A_(nn + j, local_[n]) += coef;
      rhs_[nn + j] = c.rhs;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(A_);
    if (lu.isInvertible()) {
      x_ = lu.solve(rhs_);
    } else {
      // Redundant constraints (several stuck elements on one rigid shaft): the accelerations
      // are unique, the split of the constraint torques is not; take the minimum-norm split.
      x_ = A_.completeOrthogonalDecomposition().solve(rhs_);
      const Eigen::MatrixXd kernel = lu.kernel();
      double worst = 0.0;
      for (int c = 0; c < kernel.cols(); ++c)
        worst = std::max(worst, kernel.col(c).head(nn).norm() / kernel.col(c).norm());
      const double residual = (A_ * x_ - rhs_).norm();
      if (worst > 1e-8 || residual > 1e-8 * (1.0 + rhs_.norm())) {
        std::vector<std::string> names;
        for (int n : gn) names.push_back(nodes_[n].name);
        std::vector<std::string> owners;
        for (int k : gk) owners.push_back(elements_[e.constraints[k].owner]->id);
        error_element_ = owners.empty() ? "" : owners.front();
        error_ = "the accelerations of the flanges " + Join(names) +
                 " are not determined (singular system of the constraints of " + Join(owners) +
                 " at t = " + std::to_string(e.t) +
                 "); add inertia to these flanges or remove redundant couplings";
        for (int n : gn) local_[n] = -1;
        return false;
      }
    }
    for (int i = 0; i < nn; ++i) e.acc[gn[i]] = x_[i];
    for (int j = 0; j < m; ++j) e.constraints[gk[j]].lambda = x_[nn + j];
    for (int n : gn) local_[n] = -1;
  }
  return true;
}

bool System::ProjectSpeeds(double* y) {
  // Minimum kinetic-energy change such that every velocity-level constraint holds:
  // min 1/2 (w' - w)^T J (w' - w)  s.t.  G w' = 0.
  Eval& e = eval_;
  std::vector<int> rows;
  for (int k = 0; k < e.n_constraints; ++k)
    if (e.constraints[k].velocity_level) rows.push_back(k);
  if (rows.empty()) return true;
  std::vector<int> node_list;
  for (int k : rows) {
    for (auto [n, c] : e.constraints[k].row)
      if (!nodes_[n].ground && local_[n] < 0) {
        local_[n] = static_cast<int>(node_list.size());
        node_list.push_back(n);
      }
  }
  const int nn = static_cast<int>(node_list.size()), m = static_cast<int>(rows.size());
  double j_max = 0.0;
  for (int n : node_list) j_max = std::max(j_max, nodes_[n].J);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nn + m, nn + m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(nn + m);
  for (int i = 0; i < nn; ++i) {
    const double weight = nodes_[node_list[i]].J + 1e-9 * (j_max + 1e-12);
    K(i, i) = weight;
    b[i] = weight * y[nodes_[node_list[i]].s_w];
  }
  for (int j = 0; j < m; ++j)
    for (auto [n, coef] : e.constraints[rows[j]].row)
      if (!nodes_[n].ground) {
        K(nn + j, local_[n]) += coef;
        K(local_[n], nn + j) += coef;
      }
  Eigen::VectorXd x = K.completeOrthogonalDecomposition().solve(b);
  double kinetic_change = 0.0;
  for (int i = 0; i < nn; ++i) {
    double& w = y[nodes_[node_list[i]].s_w];
    kinetic_change += 0.5 * nodes_[node_list[i]].J * (w * w - x[i] * x[i]);
    w = x[i];
    local_[node_list[i]] = -1;
  }
  impulsive_loss_ += std::max(kinetic_change, 0.0);
  return true;
}

System::EnergyState System::Energy() const {
  EnergyState s;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    s.kinetic += 0.5 * nodes_[n].J * eval_.w[n] * eval_.w[n];
  for (const auto& el : elements_) {
    s.potential += el->StoredEnergy(eval_);
    s.loss_power += el->LossPower(eval_);
    s.source_power += el->SourcePower(eval_);
  }
  return s;
}

void System::Roots(double* g) const {
  for (const auto& el : elements_)
    if (el->NumRoots() > 0) el->Roots(eval_, g + el->root_offset);
}

void System::RootDirections(int* direction) const {
  for (const auto& el : elements_)
    if (el->NumRoots() > 0) {
      for (int k = 0; k < el->NumRoots(); ++k) direction[el->root_offset + k] = 0;
      el->RootDirections(direction + el->root_offset);
    }
}

double System::NextTimeEvent(double t) const {
  double next = INFINITY;
  for (const auto& el : elements_) next = std::min(next, el->NextTimeEvent(t));
  return next;
}

bool System::HandleEvent(double t, double* y, bool initial, std::vector<std::string>* changes,
                         std::vector<std::string>* changed_elements, const int* root_info) {
  t_segment_ = t;
  if (root_info != nullptr)
    for (auto& el : elements_)
      for (int k = 0; k < el->NumRoots(); ++k)
        if (root_info[el->root_offset + k] != 0) el->MarkRootFired(k);
  eval_.initial = initial;
  std::vector<std::string> before;
  for (const auto& el : elements_) before.push_back(el->ModeText());
  if (!Evaluate(t, y, nullptr)) return false;
  for (auto& el : elements_)
    if (el->IsSwitching()) el->PrepareEvent(eval_);
  bool converged = false;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (!Evaluate(t, y, nullptr)) return false;
    if (!ProjectSpeeds(y)) return false;
    if (!Evaluate(t, y, nullptr)) return false;
    Element* worst = nullptr;
    double worst_violation = 0.0;
    for (auto& el : elements_) {
      if (!el->IsSwitching()) continue;
      const double v = el->Violation(eval_);
      if (v > worst_violation) {
        worst_violation = v;
        worst = el.get();
      }
    }
    if (worst == nullptr) {
      converged = true;
      break;
    }
    worst->Fix(eval_);
  }
  eval_.initial = false;
  if (!converged) {
    error_ = "the friction modes found no consistent combination at t = " + std::to_string(t) +
             " after 200 switches";
    return false;
  }
  if (!Evaluate(t, y, nullptr)) return false;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const std::string after = elements_[i]->ModeText();
    if (after != before[i]) {
      if (changes) changes->push_back(before[i] + " -> " + after);
      if (changed_elements) changed_elements->push_back(elements_[i]->id);
    }
  }
  return true;
}

void System::AfterEventRow() {
  for (auto& el : elements_) {
    el->AfterEventRow();
    el->ClearFired();
  }
}

void System::Outputs(double* out) const {
  for (std::size_t i = 0; i < elements_.size(); ++i)
    elements_[i]->Outputs(eval_, out + output_offset_[i]);
}

// --- Hydraulic nodes -------------------------------------------------------------------------
// Connected hydraulic ports form a node with one pressure p. A source (PressureSource, Tank)
// fixes p; otherwise p is a state of the compressible volumes attached (Volume, the chambers of
// a DifferentialCylinder): with capacitance C = sum(V_i/E_i),
//   dp/dt = sum(V_flow into the node) / C,
// where an element whose volume changes (a chamber V0 + A*s) adds -dV/dt to the flows. Lines and
// orifices are incompressible as in HighLift.Hydraulics, so a node without a volume or source
// would be algebraic: it is rejected with a message that names it.

void System::BuildHydraulicNodes(const Network& network) {
  std::map<std::string, int> index;
  for (const auto& el : elements_)
    for (const auto& port : el->HydraulicPorts()) {
      index[el->id + "." + port] = static_cast<int>(hydraulic_ports_.size());
      hydraulic_ports_.push_back(el->id + "." + port);
    }
  if (hydraulic_ports_.empty()) return;
  UnionFind ports(static_cast<int>(hydraulic_ports_.size()));
  for (const auto& c : network.connections()) {
    auto ia = index.find(c.a.ToString()), ib = index.find(c.b.ToString());
    if (ia == index.end() && ib == index.end()) continue;
    if (ia == index.end() || ib == index.end())
      throw InputError("connection " + c.a.ToString() + " - " + c.b.ToString() +
                       ": a hydraulic port can only be connected to a hydraulic port");
    ports.Unite(ia->second, ib->second);
  }
  std::map<int, int> root_to_node;
  std::vector<int> port_node(hydraulic_ports_.size());
  std::vector<std::vector<std::string>> members;
  for (std::size_t k = 0; k < hydraulic_ports_.size(); ++k) {
    const int r = ports.Find(static_cast<int>(k));
    auto it = root_to_node.find(r);
    if (it == root_to_node.end()) {
      it = root_to_node.emplace(r, static_cast<int>(hnodes_.size())).first;
      HydraulicNode n;
      n.name = hydraulic_ports_[k];
      hnodes_.push_back(n);
      members.emplace_back();
    }
    port_node[k] = it->second;
    members[it->second].push_back(hydraulic_ports_[k]);
  }
  for (auto& el : elements_) {
    if (el->HydraulicPorts().empty()) continue;
    el->BindHydraulic([&](const std::string& port) { return port_node[index.at(el->id + "." + port)]; });
    el->DeclareHydraulic(hnodes_);
  }
  for (std::size_t n = 0; n < hnodes_.size(); ++n)
    if (!hnodes_[n].fixed && !hnodes_[n].has_volume)
      throw InputError("hydraulic node of " + Join(members[n]) +
                       " has no volume and no source, so its pressure is undetermined; connect a "
                       "Volume (V = the line volume, e.g. 1e-5 m^3) or a PressureSource/Tank there");
  std::sort(hydraulic_ports_.begin(), hydraulic_ports_.end());
}

bool System::HydraulicDerivatives(double* ydot) {
  for (std::size_t n = 0; n < hnodes_.size(); ++n) {
    const HydraulicNode& h = hnodes_[n];
    if (h.s_p < 0) continue;
    if (!(eval_.cap[n] > 0.0)) {
      error_ = "hydraulic node '" + h.name + "' has no positive capacitance at t = " +
               std::to_string(eval_.t) + "; check the volumes attached to it";
      return false;
    }
    ydot[h.s_p] = eval_.q[n] / eval_.cap[n];
  }
  return true;
}

void System::PeakTorques(std::vector<double>& tau) const {
  tau.resize(elements_.size());
  for (std::size_t i = 0; i < elements_.size(); ++i) tau[i] = elements_[i]->PeakTorque(eval_);
}

}  // namespace highlift::sim::detail
