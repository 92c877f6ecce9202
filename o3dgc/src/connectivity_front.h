// The state shared by the connectivity encoder and decoder: the "front" of open gates.
//
// The coder grows the decoded region triangle by triangle. A gate is a directed edge a->b of a
// decoded triangle whose other side has not been visited. Gates are kept in per-vertex intrusive
// lists (gates leaving / entering each vertex) and on a stack that fixes the traversal order. The
// encoder and the decoder drive this structure with the same operations in the same order, so their
// states stay identical and every coded symbol can use it as context.
#ifndef O3DGC_SRC_CONNECTIVITY_FRONT_H_
#define O3DGC_SRC_CONNECTIVITY_FRONT_H_

#include <cstdint>
#include <vector>

#include "arithmetic_coder.h"
#include "entropy.h"

namespace o3dgc {

constexpr int kConnectivityContexts = 64;

struct ConnectivityModels {
  BitModel more_components;
  BitModel start_new;
  EGModel start_ref;
  BitModel attach[kConnectivityContexts];
  BitModel is_new[kConnectivityContexts];
  BitModel is_right[kConnectivityContexts];
  BitModel is_left[kConnectivityContexts];
  EGModel other_ref;
  BitModel flip;
  EGModel copies;
  BitModel copy_flip;
  EGModel extra_count;
};

class Front {
 public:
  struct Gate {
    uint32_t a, b;
    int32_t next_out, prev_out, next_in, prev_in;
    uint32_t edge;  // triangle * 4 + slot of the decoded triangle this gate is an edge of
  };
  static constexpr uint32_t kNoEdge = 0xFFFFFFFFu;
  static constexpr int kMaxScan = 64;

  void Reserve(size_t vertices, size_t triangles) {
    head_out_.reserve(vertices);
    head_in_.reserve(vertices);
    deg_.reserve(vertices);
    stack_.reserve(triangles + 16);
  }
  uint32_t AddVertex() {
    head_out_.push_back(-1);
    head_in_.push_back(-1);
    deg_.push_back(0);
    return uint32_t(deg_.size() - 1);
  }
  uint32_t num_vertices() const { return uint32_t(deg_.size()); }
  bool empty() const { return stack_.empty(); }
  // Pops the next gate; returns -1 if it was closed meanwhile. Closed gates' slots are reused,
  // so the gate storage stays as small (and as cache-resident) as the front; a stack entry is
  // valid only while its slot's generation is unchanged.
  int32_t Pop() {
    const StackEntry e = stack_.back();
    stack_.pop_back();
    return (open_[e.gate] && generation_[e.gate] == e.generation) ? e.gate : -1;
  }
  const Gate& gate(int32_t g) const { return gates_[g]; }

  int Context(uint32_t a, uint32_t b) const {
    const int has_r = head_out_[b] >= 0;
    const int has_l = head_in_[a] >= 0;
    const uint32_t d = deg_[b] < 7 ? deg_[b] : 7;
    const uint32_t da = deg_[a] >= 5 ? 1 : 0;
    return int(((has_r + 2 * has_l) * 2 + da) * 8 + d);
  }
  // Candidate third vertices: the end of the newest gate leaving b, the start of the newest gate
  // entering a (-1 if none).
  int64_t RightCandidate(uint32_t b) const {
    return head_out_[b] >= 0 ? int64_t(gates_[head_out_[b]].b) : -1;
  }
  int64_t LeftCandidate(uint32_t a) const {
    return head_in_[a] >= 0 ? int64_t(gates_[head_in_[a]].a) : -1;
  }

  void Close(int32_t g) {
    Gate& x = gates_[g];
    open_[g] = 0;
    free_.push_back(g);
    if (x.prev_out >= 0) gates_[x.prev_out].next_out = x.next_out; else head_out_[x.a] = x.next_out;
    if (x.next_out >= 0) gates_[x.next_out].prev_out = x.prev_out;
    if (x.prev_in >= 0) gates_[x.prev_in].next_in = x.next_in; else head_in_[x.b] = x.next_in;
    if (x.next_in >= 0) gates_[x.next_in].prev_in = x.prev_in;
  }

  // A new triangle edge u->v (edge = triangle * 4 + slot, the slot being the corner opposite the
  // edge): closes the open gate v->u if there is one (the two triangles become neighbours), else
  // opens u->v.
  // Only the kMaxScan newest gates leaving v are searched, so a vertex with very many open gates
  // (hostile streams, pathological meshes) cannot make coding quadratic; the encoder and the
  // decoder apply the same rule.
  void AddHalfEdge(uint32_t u, uint32_t v, uint32_t edge) {
    int scanned = 0;
    for (int32_t g = head_out_[v]; g >= 0 && scanned < kMaxScan;
         g = gates_[g].next_out, ++scanned) {
      if (gates_[g].b == u) {
        Link(edge, gates_[g].edge);
        Close(g);
        return;
      }
    }
    int32_t id;
    if (free_.empty()) {
      id = int32_t(gates_.size());
      gates_.emplace_back();
      open_.push_back(0);
      generation_.push_back(0);
    } else {
      id = free_.back();
      free_.pop_back();
      ++generation_[id];
    }
    gates_[id] = Gate{u, v, head_out_[u], -1, head_in_[v], -1, edge};
    open_[id] = 1;
    if (head_out_[u] >= 0) gates_[head_out_[u]].prev_out = id;
    head_out_[u] = id;
    if (head_in_[v] >= 0) gates_[head_in_[v]].prev_in = id;
    head_in_[v] = id;
    stack_.push_back(StackEntry{id, generation_[id]});
  }

  // Triangle `tri` = (x, y, z) starts a new part.
  void StartTriangle(uint32_t tri, uint32_t x, uint32_t y, uint32_t z) {
    ++deg_[x];
    ++deg_[y];
    ++deg_[z];
    AddHalfEdge(x, y, tri * 4 + 2);
    AddHalfEdge(y, z, tri * 4 + 0);
    AddHalfEdge(z, x, tri * 4 + 1);
  }
  // Attaches triangle `tri` across the gate g = a->b; it is emitted as (b, a, c), or as (a, b, c)
  // when `flipped`.
  void Attach(int32_t g, uint32_t tri, uint32_t a, uint32_t b, uint32_t c, bool flipped) {
    Link(tri * 4 + 2, gates_[g].edge);
    Close(g);
    ++deg_[a];
    ++deg_[b];
    ++deg_[c];
    AddHalfEdge(a, c, tri * 4 + (flipped ? 1 : 0));
    AddHalfEdge(c, b, tri * 4 + (flipped ? 0 : 1));
  }
  // Neighbour relation found while coding: for triangle t and slot k (the edge opposite corner k),
  // opposite()[3t+k] is the neighbour's triangle * 4 + slot, or kNoEdge. Sized for `triangles`.
  std::vector<uint32_t> TakeOpposite(size_t triangles) {
    opp_.resize(3 * triangles, kNoEdge);  // grows with kNoEdge, or drops the spare capacity
    return std::move(opp_);
  }

 private:
  void Link(uint32_t e1, uint32_t e2) {
    const size_t need = 3 * size_t((e1 > e2 ? e1 : e2) / 4 + 1);
    if (opp_.size() < need) opp_.resize(need > 2 * opp_.size() ? need : 2 * opp_.size(), kNoEdge);
    opp_[3 * size_t(e1 / 4) + e1 % 4] = e2;
    opp_[3 * size_t(e2 / 4) + e2 % 4] = e1;
  }

  struct StackEntry {
    int32_t gate;
    uint32_t generation;
  };
  std::vector<Gate> gates_;
  std::vector<uint8_t> open_;
  std::vector<uint32_t> generation_;
  std::vector<int32_t> free_;
  std::vector<uint32_t> opp_;
  std::vector<int32_t> head_out_, head_in_;
  std::vector<uint32_t> deg_;
  std::vector<StackEntry> stack_;
};

}  // namespace o3dgc

#endif  // O3DGC_SRC_CONNECTIVITY_FRONT_H_
