// What a stage that runs in rounds shares (tile_raster.comp, tile_sort.comp; the rules are
// tile_frame_budgets.hpp's): the rounds' indirect dispatches, and the request for the next one.
// Included after tile_common.glsl and the stage's own buffer of its rounds' arguments,
// `roundArgs` (three words a round; the raster's and the sort's are two bindings, so that every
// buffer of a frame is bound once).

// Asks for the next round of the stage being run: its whole dispatch (every job; those done
// return at once). Every job that stops writes the same three words.
void askNextRound() {
  const uint next = 3u * (frame.round + 1u);
  atomicExchange(roundArgs[next], frame.roundGroupsX);
  atomicExchange(roundArgs[next + 1u], frame.roundGroupsY);
  atomicExchange(roundArgs[next + 2u], 1u);
}
