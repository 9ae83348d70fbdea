// A chunk the selection's walk kept, as the second word of its key (terrain_select.comp's
// SelectionKeys): its slot in the low 24 bits; what terrain_hidden.comp found: the top bit when
// none of the chunk is seen (nearer terrain hides it, or it lies outside the view), or else how
// many of its blocks of cells come last, and unseen, in one of the block orders
// (terrain::BlockAtPosition), for its draw to leave them out (terrain::ChunkBlockIndexRange).
// A chunk's cells in blocks of 2 x 2, kChunkBlocks a side (terrain::kChunkBlocks), block (i, j)
// numbered j * kChunkBlocks + i; the horizon's passes take kBlockChunksPerGroup chunks a workgroup,
// an invocation per block (terrain_occluders.comp, terrain_hidden.comp).
const uint kChunkBlocks = 4u;
const uint kBlocksPerChunk = kChunkBlocks * kChunkBlocks;
const uint kBlockChunksPerGroup = 4u;
// A block's band as a target (terrain_occluders.comp's BlockTargets) when it lies outside the view:
// left out of its chunk's draw as a hidden one is.
const float kOutsideView = -2.0;

const uint kSlotMask = 0x00ffffffu;
const uint kHidden = 0x80000000u;
const uint kBlockIndices = 24u;  // terrain::kBlockIndices

uint SlotOfKey(uint word) { return word & kSlotMask; }
uint BlockOrderOfKey(uint word) { return (word >> 24u) & 3u; }
uint BlocksLeftOutOfKey(uint word) { return (word >> 26u) & 15u; }
uint WithBlocksLeftOut(uint word, uint order, uint left_out) { return word | (order << 24u) | (left_out << 26u); }
