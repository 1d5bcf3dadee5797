#!/usr/bin/env bash
# Runs a test binary of the sanitizer build with the sanitizer options (tests/CMakeLists.txt makes it the
# CROSSCOMPILING_EMULATOR of every test executable, so gtest discovery runs under it too). Options already
# in the environment come first and these are appended, so the ones here win.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=1:halt_on_error=1:abort_on_error=0:print_stacktrace=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$here/lsan.supp:print_suppressions=0"
exec "$@"
