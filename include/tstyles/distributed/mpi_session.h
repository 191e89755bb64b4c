// The MPI run a distributed command takes part in: MPI started for the session's life, this
// process's rank, and failure handled together, so that one process's bad block or lack of memory
// ends every process with one message instead of leaving the others waiting.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tstyles {

// Thrown on the processes other than 0 when a step failed somewhere: process 0 reports it and ends
// with the exit code; the others end quietly (the command line lets them exit 0, so that mpirun,
// which stops a job at the first non-zero exit, cannot stop process 0 before it has said why).
class FailedOnAnotherProcess : public std::runtime_error {
public:
    FailedOnAnotherProcess() : std::runtime_error("failed on another process") {}
};

class MpiSession {
public:
    // Starts MPI (a process started without mpirun is a run of one).
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int processCount() const { return processCount_; }
    bool isFirst() const { return rank_ == 0; }

    // Runs `work` on every process (collective). If it throws on any, every process learns it:
    // process 0 throws an error of the gravest kind among them (InputError, GlUnavailableError,
    // else std::runtime_error) whose message names each failing process and its message; the
    // others throw FailedOnAnotherProcess. `step` names the step for messages ("reading").
    void together(const std::string& step, const std::function<void()>& work) const;

    // Collective maximum of a value over the processes, on every process.
    double maximum(double value) const;
    // Collective, element by element over the processes (every process gives as many), on every
    // process: the sums, the minima and the maxima.
    std::vector<double> sum(std::vector<double> values) const;
    std::vector<double> minimum(std::vector<double> values) const;
    std::vector<double> maximum(std::vector<double> values) const;
    // Collective: every process's values one after the other, in rank order, on every process.
    std::vector<double> gathered(const std::vector<double>& values) const;

    // Point-to-point: bytes of any length to one process, which receives them with `receive` from
    // this one. Messages between two processes arrive in the order they were sent. Blocking.
    void send(int process, const std::vector<std::uint8_t>& bytes) const;
    std::vector<std::uint8_t> receive(int process) const;

private:
    int rank_ = 0;
    int processCount_ = 1;
};

}  // namespace tstyles
