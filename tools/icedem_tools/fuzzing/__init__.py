"""The input fuzzer: mutated inputs, outputs aimed at a user's files, damaged checkpoints and outputs."""
