#version 460
// Depth only: nothing to shade (the pipeline needs a fragment stage).
void main() {}
