// Runs the staged meshlabserver (build/mlstage, which loads the freshly built plugin) on the one
// Xvfb display the CTest fixture started, with a private HOME per run (the GUI and the server
// write a config file under HOME that would otherwise change later runs).
#ifndef QMF_TESTS_MESHLAB_RUNNER_H
#define QMF_TESTS_MESHLAB_RUNNER_H

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>

namespace qmf_test {

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout + stderr (meshlabserver prints the filter log there)
};

inline std::string ReadText(const std::string &path)
{
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline bool FileExists(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0 && st.st_size > 0;
}

inline std::string Quote(const std::string &s)
{
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// A fresh, empty work folder for one test (its own HOME too), under the build tree.
inline std::string WorkDir(const std::string &name)
{
    std::string dir = std::string(QMF_TEST_WORK_DIR) + "/" + name;
    std::system(("rm -rf " + Quote(dir) + " && mkdir -p " + Quote(dir + "/home")).c_str());
    return dir;
}

// The display of the fixture's Xvfb (written by tests/integration/xvfb.sh), else $DISPLAY.
inline std::string Display()
{
    std::string d = ReadText(std::string(QMF_TEST_WORK_DIR) + "/xvfb.display");
    while (!d.empty() && (d.back() == '\n' || d.back() == ' ')) d.pop_back();
    if (d.empty() && std::getenv("DISPLAY")) d = std::getenv("DISPLAY");
    return d;
}

// Runs `meshlabserver <args>` in `dir` (relative paths resolve there).
inline RunResult RunMeshLabServer(const std::string &dir, const std::string &args)
{
    RunResult r;
    std::string log = dir + "/meshlabserver.log";
    std::string cmd = "cd " + Quote(dir) + " && HOME=" + Quote(dir + "/home") + " DISPLAY=" + Quote(Display()) +
                      " XDG_RUNTIME_DIR=" + Quote(dir + "/home") + " LC_ALL=C " + Quote(std::string(QMF_STAGE_DIR) + "/bin/meshlabserver") +
                      " " + args + " > " + Quote(log) + " 2>&1";
    int status = std::system(cmd.c_str());
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.output = ReadText(log);
    return r;
}

// Path of a shipped filter script.
inline std::string Script(const std::string &name) { return std::string(QMF_SCRIPTS_DIR) + "/" + name; }

}  // namespace qmf_test

#endif
