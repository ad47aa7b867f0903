//! Verification of the published figures and tables (being written: issue 7).
