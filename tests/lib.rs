//! Cross-chapter tests live in `tests/tests/`.
