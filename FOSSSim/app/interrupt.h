#pragma once

namespace fosssim {

/// Installs a SIGINT/SIGTERM handler that only records the request, so that long runs can stop
/// between steps and keep what they computed.
void install_interrupt_handler();

/// True once Ctrl-C (or SIGTERM) was received.
bool interrupt_requested();

}  // namespace fosssim
