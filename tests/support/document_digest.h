// A digest of everything the filters write into a MeshDocument (every layer's positions bit-exact,
// face order, face-vertex indices, the face and vertex flags the filters own, quality, colours,
// edges), of the log lines with their times removed, and of files the filters exported. The
// golden-output gate compares it with committed values, so any change of behaviour is seen.
#ifndef QMF_TESTS_DOCUMENT_DIGEST_H
#define QMF_TESTS_DOCUMENT_DIGEST_H

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <common/meshmodel.h>

namespace qmf_test {

// FNV-1a, 64 bit: stable across runs, platforms and compilers (unlike std::hash).
class Digest
{
public:
    void Bytes(const void *data, size_t n)
    {
        const unsigned char *p = static_cast<const unsigned char *>(data);
        for (size_t i = 0; i < n; ++i) { h ^= p[i]; h *= 1099511628211ull; }
    }
    template <class T>
    void Value(const T &v) { Bytes(&v, sizeof(T)); }
    void Text(const std::string &s) { Value(uint64_t(s.size())); Bytes(s.data(), s.size()); }
    std::string Hex() const
    {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
        return buf;
    }

private:
    uint64_t h = 14695981039346656037ull;
};

// The flags the filters set on purpose (scratch bits such as VISITED are not part of the output).
inline int OwnedFaceFlags(const CFaceO &f)
{
    const int faceEdgeSel = CFaceO::FACEEDGESEL0 | CFaceO::FACEEDGESEL1 | CFaceO::FACEEDGESEL2;
    const int faux = CFaceO::FAUX0 | CFaceO::FAUX1 | CFaceO::FAUX2;
    return f.cFlags() & (faceEdgeSel | faux | CFaceO::SELECTED | CFaceO::DELETED);
}
inline int OwnedVertexFlags(const CVertexO &v) { return v.cFlags() & (CVertexO::SELECTED | CVertexO::DELETED); }

inline void AddLayer(Digest &d, MeshModel &mm)
{
    const CMeshO &m = mm.cm;
    d.Text(mm.label().toStdString());
    d.Value(int(m.vert.size()));
    d.Value(int(m.face.size()));
    d.Value(int(m.edge.size()));
    for (int mask : {int(MeshModel::MM_FACEQUALITY), int(MeshModel::MM_FACECOLOR), int(MeshModel::MM_POLYGONAL)})
        d.Value(char(mm.hasDataMask(mask)));
    for (const CVertexO &v : m.vert) {
        for (int k = 0; k < 3; ++k) d.Value(v.cP()[k]);
        d.Value(OwnedVertexFlags(v));
    }
    for (const CFaceO &f : m.face) {
        for (int k = 0; k < 3; ++k) d.Value(int(f.cV(k) ? vcg::tri::Index(m, f.cV(k)) : -1));
        d.Value(OwnedFaceFlags(f));
        if (mm.hasDataMask(MeshModel::MM_FACEQUALITY)) d.Value(f.cQ());
        if (mm.hasDataMask(MeshModel::MM_FACECOLOR)) for (int k = 0; k < 4; ++k) d.Value(f.cC()[k]);
    }
    for (const CEdgeO &e : m.edge)
        for (int k = 0; k < 2; ++k) d.Value(int(vcg::tri::Index(m, e.cV(k))));
}

// A log line without what differs from run to run or machine to machine: times ("0.123 s") and
// the test work folder in file paths. Everything else (counts, figures) is output.
inline std::string Portable(const std::string &line)
{
    static const std::regex seconds("[0-9]+\\.[0-9]+ s\\b");
    std::string s = std::regex_replace(line, seconds, "<time>");
    const std::string work = QMF_TEST_WORK_DIR;
    for (size_t at; (at = s.find(work)) != std::string::npos;) s.replace(at, work.size(), "<work>");
    return s;
}

inline void AddLog(Digest &d, const std::vector<std::string> &lines)
{
    for (const std::string &l : lines) d.Text(Portable(l));
}

inline void AddDocument(Digest &d, MeshDocument &doc)
{
    d.Value(int(doc.meshList.size()));
    for (MeshModel *mm : doc.meshList) AddLayer(d, *mm);
    d.Value(doc.mm() ? doc.mm()->id() : -1);
}

inline bool AddFile(Digest &d, const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    d.Text(bytes);
    return true;
}

}  // namespace qmf_test

#endif
