/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    backgroundWriter: a collected write time reaches the disk only once it
    is handed over, in the order collected (files in new directories, a
    fastOFstream's bytes as it writes them to a file, links, a directory
    removed); the first failure stops the rest and names the file and the
    reason, and a file that did not fit is removed; a process that exits
    finishes the write time handed over. A fastOFstream's uncompressed
    file of more than one piece is written as it comes, the same bytes,
    and its failure is the collection's; a compressed one is collected
    whole and deflated by the thread (one whole gzip stream, the text of
    OpenFOAM's compressed stream), replacing an uncompressed twin, or,
    beyond 16 MB, deflated as it comes; a process whose writer's thread
    runs out of memory ends, and does not wait for that thread.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "fileContents.H"
#include "backgroundWriter.H"
#include "fastOFstream.H"
#include "IFstream.H"
#include "particleMemory.H"
#include "OSspecific.H"
#include "scalarList.H"
#include <gtest/gtest.h>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

typedef backgroundWriter::operation::kind kind;

//- What a fastOFstream writes of a few numbers and words
void writeSome(Ostream& os)
{
    os  << "numbers" << token::SPACE << 0.1 << token::SPACE << -2.5e-300
        << nl << labelList({1, 2, 3}) << nl;
}

//- A file-size limit of 64 kB for this process, as a full disk: a write
//  beyond it fails with EFBIG (the signal it would raise ignored)
void limitFileSize()
{
    const rlim_t limit = 1 << 16;
    const rlimit lim{limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    std::signal(SIGXFSZ, SIG_IGN);
}

//- With a file-size limit of 64 kB (as a full disk): does a file of 1 MB
//  fail, named with the reason, removed, the file before it written?
bool writeBeyondAFileSizeLimit(const fileName& dir)
{
    limitFileSize();
    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        writer.add({kind::writeFile, dir/"small", "fits"});
        writer.add({kind::writeFile, dir/"big", std::string(1 << 20, 'x')});
        writer.submit();
    }
    const std::string failure = writer.wait();
    return
        failure.find(dir/"big") != std::string::npos
     && failure.find("File too large") != std::string::npos
     && !exists(dir/"big") && isFile(dir/"small");
}

//- A list of n numbers written to os (about 20 bytes each)
void writeNumbers(Ostream& os, const label n)
{
    scalarList values(n);
    forAll(values, i)
    {
        values[i] = 1.0/(i + 3);
    }
    fastOFstream::writeList(os, values);
    os  << nl;
}

//- With a file-size limit of 64 kB: does a fastOFstream of 1 MB, or a
//  compressed one of 24 MB (more than is collected whole), collected, go
//  bad, with its failure (named, the reason) collected and handed over,
//  and the file removed?
bool collectBeyondAFileSizeLimit(const fileName& dir, const bool compressed)
{
    limitFileSize();
    backgroundWriter writer;
    bool bad = false;
    std::string collected;
    {
        const backgroundWriter::collection collecting(writer);
        try
        {
            fastOFstream os
            (
                dir/"big", IOstream::ASCII, IOstream::currentVersion,
                compressed ? IOstream::COMPRESSED : IOstream::UNCOMPRESSED
            );
            writeNumbers(os, compressed ? 2000000 : 50000);
            os.flush();
            bad = !os.good();
        }
        catch (const Foam::error&)
        {
            // (the list's writer checks the stream: the tests throw)
            bad = true;
        }
        collected = writer.collectedFailure();
        writer.submit();
    }
    const std::string failure = writer.wait();
    return
        bad && !collected.empty() && failure == collected
     && failure.find(dir/"big") != std::string::npos
     && failure.find("File too large") != std::string::npos
     && !exists(dir/"big");
}

//- The text of a file or, where there is none, of file.gz decompressed
//  (as OpenFOAM's readers take it)
std::string decompressed(const fileName& file)
{
    IFstream is(file);
    std::stringstream text;
    text << is.stdStream().rdbuf();
    return text.str();
}

//- The text of a gzip file, decompressed strictly: false unless it is
//  one whole gzip stream (its trailer's checksum and length right) and
//  nothing after it
bool gunzipped(const fileName& file, std::string& text)
{
    std::string in = contents(file);
    text.clear();
    z_stream z{};
    if (in.empty() || inflateInit2(&z, MAX_WBITS + 16) != Z_OK)
    {
        return false;
    }
    z.next_in = reinterpret_cast<Bytef*>(&in[0]);
    z.avail_in = uInt(in.size());
    char out[1 << 16];
    int status = Z_OK;
    while (status == Z_OK)
    {
        z.next_out = reinterpret_cast<Bytef*>(out);
        z.avail_out = sizeof(out);
        status = inflate(&z, Z_NO_FLUSH);
        text.append(out, sizeof(out) - z.avail_out);
    }
    const bool whole = status == Z_STREAM_END && z.avail_in == 0;
    inflateEnd(&z);
    return whole;
}

//- With a file-size limit of 64 kB: does a compressed file whose deflated
//  bytes do not fit fail, named (.gz) with the reason, and get removed?
bool deflateBeyondAFileSizeLimit(const fileName& dir)
{
    limitFileSize();
    std::string noise(1 << 20, ' ');
    unsigned state = 12345;
    for (char& c : noise)
    {
        state = 1103515245u*state + 12345u;
        c = char(state >> 24);
    }
    std::ofstream(dir/"big") << "an earlier, uncompressed write";
    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        writer.add({kind::writeCompressed, dir/"big", noise});
        writer.submit();
    }
    const std::string failure = writer.wait();
    return
        failure.find(dir/"big.gz") != std::string::npos
     && failure.find("File too large") != std::string::npos
     && !exists(dir/"big.gz") && !exists(dir/"big", false);
}

//- A write time handed over while no memory is left to map: the writer's
//  thread fails to allocate, and the solvers' out-of-memory handler either
//  ends the process from that thread (a FatalError, exit code 1) or, with
//  errors thrown, the write time fails: exit code 2 when it says so
void runOutOfMemoryOnTheWritersThread(const fileName& dir, const bool thrown)
{
    particleMemory::exitOnOutOfMemory();
    if (!thrown)
    {
        FatalError.dontThrowExceptions();
    }
    backgroundWriter* writer = new backgroundWriter();
    {
        const backgroundWriter::collection collecting(*writer);
        writer->add({kind::writeCompressed, dir/"small", "text"});

        // No address space beyond what the process has mapped: the
        // thread's buffer of a piece (256 kB, mapped on its own) fails
        long pages = 0;
        std::ifstream("/proc/self/statm") >> pages;
        const rlim_t limit = rlim_t(pages)*::sysconf(_SC_PAGESIZE);
        const rlimit lim{limit, limit};
        ::setrlimit(RLIMIT_AS, &lim);
        writer->submit();
    }
    const std::string failure = writer->wait();
    std::exit(failure.find("out of memory") != std::string::npos ? 2 : 0);
}

//- An empty scratch directory for tests in child processes, each a new
//  process (threadsafe): OpenMP's threads do not survive a fork
fileName childProcessDir()
{
    ::testing::FLAGS_gtest_death_test_style = "threadsafe";
    const fileName dir(scratchDir("backgroundWriter"));
    rmDir(dir, true);
    mkDir(dir);
    return dir;
}

//- An empty scratch directory with n numbers written now into direct
fileName freshWithNumbers(const label n)
{
    const fileName dir(scratchDir("backgroundWriter"));
    rmDir(dir, true);
    fastOFstream os(dir/"direct");
    writeNumbers(os, n);
    return dir;
}

//- Hand nFiles files and a record over, then exit with code
void handOverAndExit
(
    const fileName& dir,
    const label nFiles,
    const std::string& bytes,
    const int code
)
{
    // Never destroyed: only the exit waits for it
    backgroundWriter* writer = new backgroundWriter();
    {
        const backgroundWriter::collection collecting(*writer);
        for (label i = 0; i < nFiles; ++i)
        {
            writer->add({kind::writeFile, dir/"d"/Foam::name(i), bytes});
        }
        writer->add({kind::writeFile, dir/"record", "last"});
        writer->submit();
    }
    std::exit(code);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(backgroundWriter, WritesACollectionInOrderOnceHandedOver)
{
    const fileName dir(scratchDir("backgroundWriter"));
    rmDir(dir, true);
    mkDir(dir/"old"/"sub");
    std::ofstream(dir/"old"/"sub"/"f") << "old";

    // Compressed twins of earlier writes: replaced
    mkDir(dir/"a"/"c");
    mkDir(dir/"a"/"d");
    std::ofstream(dir/"a"/"c"/"text.gz") << "an earlier, compressed write";
    std::ofstream(dir/"a"/"d"/"linked.gz") << "an earlier, compressed write";

    // The same bytes as a file written now
    {
        fastOFstream os(dir/"direct");
        writeSome(os);
    }

    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        EXPECT_EQ(backgroundWriter::collecting(), &writer);
        {
            fastOFstream os(dir/"a"/"b"/"collected");
            writeSome(os);
        }
        writer.add({kind::writeFile, dir/"a"/"c"/"text", "hello"});
        writer.add({kind::linkFile, dir/"a"/"d"/"linked", dir/"a"/"c"/"text"});
        writer.add({kind::removeDir, dir/"old", ""});

        // Nothing on the disk before it is handed over
        EXPECT_FALSE(exists(dir/"a"/"b"));
        EXPECT_FALSE(exists(dir/"a"/"c"/"text", false));
        writer.submit();
    }
    EXPECT_EQ(backgroundWriter::collecting(), nullptr);
    EXPECT_EQ(writer.wait(), "");

    EXPECT_EQ(contents(dir/"a"/"b"/"collected"), contents(dir/"direct"));
    EXPECT_GT(contents(dir/"direct").size(), 20u);
    EXPECT_EQ(contents(dir/"a"/"c"/"text"), "hello");
    EXPECT_EQ(inode(dir/"a"/"d"/"linked"), inode(dir/"a"/"c"/"text"));
    EXPECT_FALSE(exists(dir/"a"/"c"/"text.gz"));
    EXPECT_FALSE(exists(dir/"a"/"d"/"linked.gz"));
    EXPECT_FALSE(exists(dir/"old"));
}


TEST(backgroundWriter, StopsAtTheFirstFailureNamingTheFileAndWhy)
{
    const fileName dir(scratchDir("backgroundWriter"));
    rmDir(dir, true);
    mkDir(dir);
    std::ofstream(dir/"plain") << "a file, not a directory";

    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        writer.add({kind::writeFile, dir/"first", "1"});
        writer.add({kind::writeFile, dir/"plain"/"inside", "2"});
        writer.add({kind::writeFile, dir/"last", "3"});
        writer.submit();
    }
    const std::string failure = writer.wait();
    EXPECT_NE(failure.find(dir/"plain"/"inside"), std::string::npos)
        << failure;
    EXPECT_NE(failure.find("Not a directory"), std::string::npos) << failure;
    EXPECT_TRUE(isFile(dir/"first"));
    EXPECT_FALSE(exists(dir/"last"));

    // The writer goes on with the next write time
    {
        const backgroundWriter::collection collecting(writer);
        writer.add({kind::writeFile, dir/"next", "4"});
        writer.submit();
    }
    EXPECT_EQ(writer.wait(), "");
    EXPECT_EQ(contents(dir/"next"), "4");
}


TEST(backgroundWriter, WritesALargeFileAsItComes)
{
    const label n = 50000;
    const fileName dir(freshWithNumbers(n));
    ASSERT_GT(fileSize(dir/"direct"), 2*backgroundWriter::pieceSize);

    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        {
            fastOFstream os(dir/"a"/"large");
            writeNumbers(os, n);
            fastOFstream small(dir/"a"/"small");
            writeNumbers(small, 10);
        }
        EXPECT_EQ(writer.collectedFailure(), "");

        // The large file on the disk, whole, before the hand-over
        EXPECT_EQ(contents(dir/"a"/"large"), contents(dir/"direct"));
        EXPECT_FALSE(exists(dir/"a"/"small"));
        writer.submit();
    }
    EXPECT_EQ(writer.wait(), "");
    EXPECT_EQ(contents(dir/"a"/"large"), contents(dir/"direct"));
    EXPECT_GT(fileSize(dir/"a"/"small"), 50);
}


TEST(backgroundWriter, DeflatesACompressedFileOnItsThread)
{
    const fileName dir(scratchDir("backgroundWriter"));
    rmDir(dir, true);
    const label n = 50000;
    const IOstream::versionNumber ver = IOstream::currentVersion;
    {
        // Written now, by OpenFOAM's compressed stream
        fastOFstream os
        (
            dir/"direct", IOstream::ASCII, ver, IOstream::COMPRESSED
        );
        writeNumbers(os, n);
    }
    ASSERT_TRUE(isFile(dir/"direct.gz"));
    ASSERT_GT
    (
        decompressed(dir/"direct").size(), 2u*backgroundWriter::pieceSize
    );

    // Uncompressed twins of earlier writes: replaced
    mkDir(dir/"a");
    std::ofstream(dir/"a"/"large") << "an earlier, uncompressed write";
    std::ofstream(dir/"a"/"linked") << "an earlier, uncompressed write";

    backgroundWriter writer;
    {
        const backgroundWriter::collection collecting(writer);
        {
            fastOFstream os
            (
                dir/"a"/"large", IOstream::ASCII, ver, IOstream::COMPRESSED
            );
            writeNumbers(os, n);
        }
        EXPECT_EQ(writer.collectedFailure(), "");
        writer.add({kind::writeCompressed, dir/"a"/"empty", ""});
        writer.add
        ({
            kind::linkFile, dir/"a"/"linked.gz", dir/"a"/"large.gz"
        });

        // Collected whole, not written as it came: nothing on the disk
        EXPECT_FALSE(exists(dir/"a"/"large.gz"));
        writer.submit();
    }
    EXPECT_EQ(writer.wait(), "");
    EXPECT_FALSE(exists(dir/"a"/"large", false));
    EXPECT_EQ(contents(dir/"a"/"large.gz").substr(0, 2), "\x1f\x8b");
    EXPECT_LT(fileSize(dir/"a"/"large.gz"), fileSize(dir/"direct.gz")*3/2);
    std::string text;
    EXPECT_TRUE(gunzipped(dir/"a"/"large.gz", text));
    EXPECT_EQ(text, decompressed(dir/"direct"));
    EXPECT_TRUE(gunzipped(dir/"a"/"empty.gz", text));
    EXPECT_EQ(text, "");

    // A compressed file linked: its uncompressed twin removed
    EXPECT_FALSE(exists(dir/"a"/"linked", false));
    EXPECT_EQ(inode(dir/"a"/"linked.gz"), inode(dir/"a"/"large.gz"));
}


TEST(backgroundWriter, DeflatesALargeCompressedFileAsItComes)
{
    // More than is collected whole: deflated on this thread as it comes,
    // the memory held bounded
    const label n = 2000000;
    const fileName dir(freshWithNumbers(n));
    const std::string direct = contents(dir/"direct");
    ASSERT_GT(direct.size(), Detail::collectBuffer::wholeSize);
    mkDir(dir/"a");
    std::ofstream(dir/"a"/"large") << "an earlier, uncompressed write";

    backgroundWriter writer;
    std::string text;
    {
        const backgroundWriter::collection collecting(writer);
        {
            fastOFstream os
            (
                dir/"a"/"large", IOstream::ASCII, IOstream::currentVersion,
                IOstream::COMPRESSED
            );
            writeNumbers(os, n);
        }
        EXPECT_EQ(writer.collectedFailure(), "");

        // Whole on the disk before the hand-over, its twin removed
        EXPECT_TRUE(gunzipped(dir/"a"/"large.gz", text));
        EXPECT_TRUE(text == direct);
        EXPECT_FALSE(exists(dir/"a"/"large", false));
        writer.submit();
    }
    EXPECT_EQ(writer.wait(), "");
    EXPECT_TRUE(gunzipped(dir/"a"/"large.gz", text));
    EXPECT_TRUE(text == direct);
}


TEST(backgroundWriter, RemovesAFileThatDidNotFit)
{
    // In a child process: a file-size limit of 64 kB, as a full disk
    const fileName dir(childProcessDir());
    EXPECT_EXIT
    (
        std::exit(writeBeyondAFileSizeLimit(dir) ? 0 : 1),
        ::testing::ExitedWithCode(0),
        ""
    );
    for (const bool compressed : {false, true})
    {
        EXPECT_EXIT
        (
            std::exit(collectBeyondAFileSizeLimit(dir, compressed) ? 0 : 1),
            ::testing::ExitedWithCode(0),
            ""
        ) << (compressed ? "compressed" : "uncompressed");
    }
    EXPECT_EXIT
    (
        std::exit(deflateBeyondAFileSizeLimit(dir) ? 0 : 1),
        ::testing::ExitedWithCode(0),
        ""
    );
}


TEST(backgroundWriter, EndsWhenItsThreadRunsOutOfMemory)
{
    // The process's exit, from the writer's thread, must not wait for
    // that thread
    const fileName dir(childProcessDir());
    EXPECT_EXIT
    (
        runOutOfMemoryOnTheWritersThread(dir, false),
        ::testing::ExitedWithCode(1),
        "out of memory"
    );
    EXPECT_EXIT
    (
        runOutOfMemoryOnTheWritersThread(dir, true),
        ::testing::ExitedWithCode(2),
        ""
    );
}


TEST(backgroundWriter, FinishesTheWriteHandedOverWhenTheProcessExits)
{
    const fileName dir(childProcessDir());
    const label nFiles = 2000;
    const std::string bytes(1 << 12, 'x');
    EXPECT_EXIT
    (
        handOverAndExit(dir, nFiles, bytes, 3),
        ::testing::ExitedWithCode(3),
        ""
    );
    EXPECT_EQ(contents(dir/"record"), "last");
    label whole = 0;
    for (label i = 0; i < nFiles; ++i)
    {
        whole += fileSize(dir/"d"/Foam::name(i)) == off_t(bytes.size());
    }
    EXPECT_EQ(whole, nFiles);
}


// ************************************************************************* //
