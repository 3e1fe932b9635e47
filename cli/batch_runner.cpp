#include "batch_runner.hpp"

#include "railodd/util/errors.hpp"

#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace railodd::cli {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

BatchProgress::BatchProgress(std::size_t total, unsigned jobs, bool terminal, std::string noun)
    : total_(total), jobs_(jobs), terminal_(terminal), noun_(std::move(noun)) {}

void BatchProgress::clear_line() {
    if (line_shown_) {
        std::cerr << "\r\033[K";
        line_shown_ = false;
    }
}

void BatchProgress::finished(const std::string& id, const std::string& status, double seconds,
                             const std::string& detail) {
    ++done_;
    last_finish_ = Clock::now();
    if (status != "skipped") {
        ++ran_;
        ran_seconds_ += seconds;
    }
    clear_line();
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.1f s", seconds);
    std::cerr << '[' << done_ << '/' << total_ << "] " << status << ' ' << id;
    if (status != "skipped") {
        std::cerr << ' ' << secs;
    }
    std::cerr << (detail.empty() ? "" : ": ") << detail << '\n';
}

void BatchProgress::running(const std::vector<std::pair<std::string, std::string>>& id_phase) {
    if (!terminal_) {
        return;
    }
    std::ostringstream line;
    line << noun_ << ' ' << done_ << '/' << total_ << ", running:";
    for (const auto& [id, phase] : id_phase) {
        line << ' ' << id << " (" << phase << ')';
    }
    // Estimate from the routes finished so far, spread over the job slots,
    // counting down between finishes.
    const std::size_t left = total_ - done_;
    if (ran_ > 0 && left > 0) {
        const double since = std::chrono::duration<double>(Clock::now() - last_finish_).count();
        const double eta = std::max(0.0, ran_seconds_ / ran_ * std::ceil(double(left) / jobs_) - since);
        line << ", ETA " << static_cast<long>(eta + 0.5) << " s";
    }
    std::string text = line.str();
    winsize ws{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1 && text.size() >= ws.ws_col) {
        text.resize(ws.ws_col - 1); // a wrapped line could not be redrawn with \r
    }
    std::cerr << "\r\033[K" << text << std::flush;
    line_shown_ = true;
}

void BatchProgress::close() { clear_line(); }

namespace {

// The last "railodd: ..." line of a failed step's log (main() prints every
// error that way), else its last non-empty line.
std::string error_line(const fs::path& log) {
    std::ifstream in(log);
    std::string line, last, last_railodd;
    while (std::getline(in, line)) {
        if (!line.empty()) {
            last = line;
        }
        if (line.rfind("railodd: ", 0) == 0) {
            last_railodd = line;
        }
    }
    std::string e = last_railodd.empty() ? last : last_railodd;
    return e.size() > 400 ? e.substr(0, 400) + "..." : e;
}

// A log over `cap` bytes keeps its first and last cap/2 bytes, with a line
// saying how much was cut between them.
void cap_log(const fs::path& log, std::uintmax_t cap) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(log, ec);
    if (cap == 0 || ec || size <= cap) {
        return;
    }
    const std::uintmax_t half = cap / 2;
    std::string head(half, '\0'), tail(half, '\0');
    {
        std::ifstream in(log, std::ios::binary);
        in.read(head.data(), static_cast<std::streamsize>(half));
        in.seekg(static_cast<std::streamoff>(size - half));
        in.read(tail.data(), static_cast<std::streamsize>(half));
    }
    std::ofstream out(log, std::ios::binary | std::ios::trunc);
    out << head << "\n[railodd: " << size - 2 * half << " bytes of this log left out]\n" << tail;
}

// posix_spawn: vfork semantics, so a large parent is not copied per route.
pid_t spawn(const BatchStep& step, std::string& error) {
    std::vector<std::string> args{step.program.empty() ? "railodd" : step.program};
    args.insert(args.end(), step.args.begin(), step.args.end());
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, step.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addchdir_np(&fa, step.cwd.c_str());
    // A group of its own: a timeout or an interrupt kills what the step
    // started too (a player's helper processes), not only the step.
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
    pid_t pid = -1;
    const std::string program = step.program.empty() ? "/proc/self/exe" : step.program;
    const int rc = ::posix_spawn(&pid, program.c_str(), &fa, &attr, argv.data(), environ);
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        error = "cannot start " + (step.program.empty() ? "railodd " + step.name : step.program) + ": " + std::strerror(rc);
        return -1;
    }
    return pid;
}

struct Running {
    std::size_t task = 0;
    std::size_t step = 0;
    pid_t pid = -1;
    Clock::time_point start;
    TaskOutcome outcome;
    double timed_out_after = 0.0; // > 0: killed for running longer than this
};

// Starts the running task's current step; false (outcome filled) if it could not.
bool start_step(const std::vector<BatchTask>& tasks, Running& r) {
    std::string error;
    r.pid = spawn(tasks[r.task].steps[r.step], error);
    if (r.pid < 0) {
        r.outcome.exit_code = exit_internal;
        r.outcome.failed_step = tasks[r.task].steps[r.step].name;
        r.outcome.error = error;
        return false;
    }
    return true;
}

// Records the exit of r's current step; true when the task is finished.
bool step_exited(const std::vector<BatchTask>& tasks, Running& r, int status, const rusage& ru) {
    TaskOutcome& o = r.outcome;
    o.peak_rss_kb = std::max(o.peak_rss_kb, static_cast<long>(ru.ru_maxrss));
    const BatchStep& step = tasks[r.task].steps[r.step];
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!ok) {
        o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        o.failed_step = step.name;
        o.error = WIFSIGNALED(status) ? std::string{"killed by signal "} + std::to_string(WTERMSIG(status))
                                      : error_line(step.log);
        if (r.timed_out_after > 0.0) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "timed out: still running after %g s (", r.timed_out_after);
            o.error = buf + tasks[r.task].timeout_option + "), killed";
        }
        cap_log(step.log, step.log_cap);
        return true;
    }
    cap_log(step.log, step.log_cap);
    if (++r.step < tasks[r.task].steps.size()) {
        return !start_step(tasks, r);
    }
    o.ok = true;
    return true;
}

} // namespace

namespace {

volatile std::sig_atomic_t interrupt_signal = 0;

extern "C" void note_interrupt(int sig) { interrupt_signal = sig; }

// While run_tasks waits, SIGINT and SIGTERM are only noted: it then kills its
// children and unwinds, instead of dying with them still running and its
// folders left behind.
class InterruptGuard {
public:
    InterruptGuard() {
        interrupt_signal = 0;
        struct sigaction sa {};
        sa.sa_handler = note_interrupt;
        sigemptyset(&sa.sa_mask);
        ::sigaction(SIGINT, &sa, &old_int_);
        ::sigaction(SIGTERM, &sa, &old_term_);
    }
    ~InterruptGuard() {
        ::sigaction(SIGINT, &old_int_, nullptr);
        ::sigaction(SIGTERM, &old_term_, nullptr);
    }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

void stop_on_interrupt(std::vector<Running>& running) {
    const int sig = interrupt_signal;
    if (sig == 0) {
        return;
    }
    for (const auto& r : running) {
        ::kill(-r.pid, SIGKILL);
    }
    for (const auto& r : running) {
        int status = 0;
        while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    throw Interrupted(sig);
}

// A task past its time is killed; wait4 then reaps it as failed.
void kill_overdue(const std::vector<BatchTask>& tasks, std::vector<Running>& running) {
    const auto now = Clock::now();
    for (auto& r : running) {
        const double timeout_s = tasks[r.task].timeout_s;
        if (timeout_s > 0.0 && r.timed_out_after == 0.0 &&
            std::chrono::duration<double>(now - r.start).count() > timeout_s) {
            ::kill(-r.pid, SIGKILL);
            r.timed_out_after = timeout_s;
        }
    }
}

} // namespace

void run_tasks(const std::vector<BatchTask>& tasks, unsigned jobs, BatchProgress& progress,
               const std::function<void(std::size_t, const TaskOutcome&)>& on_done) {
    const InterruptGuard guard;
    std::vector<Running> running;
    std::size_t next = 0;
    auto finish = [&](Running& r) {
        r.outcome.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
        on_done(r.task, r.outcome);
    };
    while (next < tasks.size() || !running.empty()) {
        while (running.size() < jobs && next < tasks.size()) {
            Running r{next++, 0, -1, Clock::now(), {}};
            if (start_step(tasks, r)) {
                running.push_back(std::move(r));
            } else {
                finish(r);
            }
        }
        std::vector<std::pair<std::string, std::string>> shown;
        for (const auto& r : running) {
            shown.emplace_back(tasks[r.task].id, tasks[r.task].steps[r.step].name);
        }
        progress.running(shown);
        stop_on_interrupt(running);
        kill_overdue(tasks, running);
        int status = 0;
        rusage ru{};
        const pid_t pid = ::wait4(-1, &status, WNOHANG, &ru);
        if (pid == 0 || (pid < 0 && errno == EINTR)) {
            // Polling keeps the ETA line moving; 0.2 s is nothing beside a route.
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            continue;
        }
        if (pid < 0) {
            throw std::runtime_error(std::string{"batch: wait4: "} + std::strerror(errno));
        }
        for (auto it = running.begin(); it != running.end(); ++it) {
            if (it->pid == pid) {
                if (step_exited(tasks, *it, status, ru)) {
                    finish(*it);
                    running.erase(it);
                }
                break;
            }
        }
    }
}

} // namespace railodd::cli
