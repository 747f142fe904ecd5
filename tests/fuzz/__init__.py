"""The fuzzing campaign against bad input (scripts/fuzz runs it; tests/test_fuzz_corpus.py replays its
kept corpus): mutations of valid case files, --set overrides and workflow configs, corrupted result
files, and the rules every outcome must meet."""
