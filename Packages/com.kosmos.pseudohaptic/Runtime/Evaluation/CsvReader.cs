using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The one CSV reader of the package and the tool (traces, responses, scores, trial files), streaming, one
    /// record at a time in constant memory. RFC 4180: fields separated by commas; a field in double quotes may
    /// hold commas, line breaks and doubled quotes (<c>"say ""hi"""</c>); records end with LF, CRLF or CR.
    /// UTF-8 with or without a byte-order mark (a leading U+FEFF is dropped). Beyond RFC 4180: spaces and tabs
    /// around a field are not part of it; blank lines (nothing but spaces) are skipped. Every data record must
    /// have exactly as many fields as the header. A record longer than <see cref="MaxRecordLength"/> characters
    /// (1 MiB by default; a line without an end, such as /dev/zero, is one) is refused. Every fault throws
    /// <see cref="EvaluationFormatException"/> naming the source and the line the record starts on (the
    /// header's line is 1 unless blank lines precede it).
    /// </summary>
    public sealed class CsvReader : IDisposable
    {
        /// <summary>The default longest record, in characters: 1 MiB.</summary>
        public const int DefaultMaxRecordLength = 1 << 20;

        readonly TextReader reader;
        readonly bool leaveOpen;
        readonly char[] buffer = new char[16384];
        int bufferPos, bufferLength;
        bool atEnd, started;
        int nextLine = 1;

        char[] record = new char[256];
        int recordLength, consumed;
        readonly List<int> starts = new List<int>(), lengths = new List<int>();
        string[] header;

        /// <summary>Reads <paramref name="reader"/>; <paramref name="sourceName"/> goes into every message.</summary>
        public CsvReader(TextReader reader, string sourceName, int maxRecordLength = DefaultMaxRecordLength, bool leaveOpen = false)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            if (maxRecordLength < 1) throw new ArgumentOutOfRangeException(nameof(maxRecordLength), "must be at least 1");
            this.reader = reader;
            this.leaveOpen = leaveOpen;
            SourceName = sourceName ?? "";
            MaxRecordLength = maxRecordLength;
        }

        public string SourceName { get; }

        /// <summary>The longest record accepted, in characters (line breaks inside quotes included).</summary>
        public int MaxRecordLength { get; }

        /// <summary>The header's fields, once <see cref="ReadHeader"/> returned true.</summary>
        public IReadOnlyList<string> Header => header;

        /// <summary>The line the header starts on.</summary>
        public int HeaderLine { get; private set; }

        /// <summary>The line the record last read starts on.</summary>
        public int Line { get; private set; }

        /// <summary>The line the record last read ends on (greater than <see cref="Line"/> when a quoted field holds a line break).</summary>
        public int EndLine { get; private set; }

        /// <summary>Fields of the record last read.</summary>
        public int FieldCount => starts.Count;

        /// <summary>A field of the record last read, as a new string.</summary>
        public string this[int index] => new string(record, starts[index], lengths[index]);

        /// <summary>A field of the record last read, without allocating; valid until the next read.</summary>
        public ReadOnlySpan<char> Span(int index) => new ReadOnlySpan<char>(record, starts[index], lengths[index]);

        /// <summary>Reads the header (the first record that is not blank); false when the source holds nothing but blank lines.</summary>
        public bool ReadHeader()
        {
            if (header != null) throw new InvalidOperationException("the header was read already");
            if (!ReadRecord()) return false;
            header = new string[FieldCount];
            for (int i = 0; i < header.Length; i++) header[i] = this[i];
            HeaderLine = Line;
            return true;
        }

        /// <summary>Position of the header column named <paramref name="name"/>, or −1; a name found twice is an error on the header's line.</summary>
        public int IndexOf(string name, StringComparison comparison = StringComparison.Ordinal)
        {
            if (header == null) throw new InvalidOperationException("read the header first");
            int found = -1;
            for (int i = 0; i < header.Length; i++)
            {
                if (!string.Equals(header[i], name, comparison)) continue;
                if (found >= 0) throw Error(HeaderLine, "column '" + name + "' appears twice in the header");
                found = i;
            }
            return found;
        }

        /// <summary>Reads the next data record (after the header, when one was read); false at the end.</summary>
        public bool Read()
        {
            if (!ReadRecord()) return false;
            if (header != null && FieldCount != header.Length)
                throw Error(Line, "expected " + header.Length.ToString(CultureInfo.InvariantCulture) + " fields as in the header, found "
                                  + FieldCount.ToString(CultureInfo.InvariantCulture));
            return true;
        }

        /// <summary>An error on <paramref name="line"/> of this source.</summary>
        public EvaluationFormatException Error(int line, string reason) => new EvaluationFormatException(SourceName, line, reason);

        /// <summary>Reads the next record that is not blank, whatever its field count.</summary>
        bool ReadRecord()
        {
            for (;;)
            {
                starts.Clear();
                lengths.Clear();
                recordLength = 0;
                consumed = 0;
                if (Peek() < 0) return false;
                Line = nextLine;
                bool blank = true;
                int c = -1;
                for (;;)
                {
                    // One field. Spaces before it are not part of it, nor do they stop it being quoted.
                    c = NextOutsideQuotes();
                    while (c == ' ' || c == '\t') c = NextOutsideQuotes();
                    int start = recordLength;
                    if (c == '"')
                    {
                        blank = false;
                        for (;;)
                        {
                            CopyQuoted();
                            c = Next();
                            if (c < 0) throw Error(Line, "unterminated quoted field: no closing quote before the end of the file");
                            if (c == '"')
                            {
                                if (Peek() != '"') break;
                                Next();
                            }
                            else if (c == '\n' || (c == '\r' && Peek() != '\n')) nextLine++;
                            Append((char)c);
                        }
                        int end = recordLength;
                        c = NextOutsideQuotes();
                        while (c == ' ' || c == '\t') c = NextOutsideQuotes();
                        starts.Add(start);
                        lengths.Add(end - start);
                        if (c != ',' && c >= 0 && c != '\n' && c != '\r')
                            throw Error(Line, "text after the closing quote of field " + starts.Count.ToString(CultureInfo.InvariantCulture) + " (quote the whole field)");
                    }
                    else
                    {
                        if (c >= 0 && c != ',' && c != '\n' && c != '\r')
                        {
                            if (c == '"') throw QuoteInside();
                            Append((char)c);
                            c = ScanUnquoted();
                        }
                        int end = recordLength;
                        while (end > start && (record[end - 1] == ' ' || record[end - 1] == '\t')) end--;
                        if (end > start || c == ',') blank = false;
                        starts.Add(start);
                        lengths.Add(end - start);
                    }
                    if (c == ',') continue;
                    if (c == '\r')
                    {
                        if (Peek() == '\n') NextOutsideQuotes();
                        nextLine++;
                    }
                    else if (c == '\n') nextLine++;
                    break;
                }
                EndLine = c < 0 ? nextLine : nextLine - 1;
                if (!blank) return true;
            }
        }

        static readonly char[] UnquotedStops = { ',', '\n', '\r', '"' };
        static readonly char[] QuotedStops = { '"', '\n', '\r' };

        EvaluationFormatException QuoteInside()
            => Error(Line, "a quote inside unquoted field " + (starts.Count + 1).ToString(CultureInfo.InvariantCulture) + " (quote the whole field and double the quote)");

        /// <summary>Copies the rest of an unquoted field in bulk; returns the character that ended it (consumed), or −1.</summary>
        int ScanUnquoted()
        {
            for (;;)
            {
                if (bufferPos >= bufferLength && !Fill()) return -1;
                var rest = new ReadOnlySpan<char>(buffer, bufferPos, bufferLength - bufferPos);
                int stop = rest.IndexOfAny(UnquotedStops);
                int take = stop < 0 ? rest.Length : stop;
                Take(rest.Slice(0, take));
                if (stop < 0) continue;
                int c = NextOutsideQuotes();
                if (c == '"') throw QuoteInside();
                return c;
            }
        }

        /// <summary>Copies the plain characters of a quoted field in bulk, up to a quote or a line break (not consumed).</summary>
        void CopyQuoted()
        {
            for (;;)
            {
                if (bufferPos >= bufferLength && !Fill()) return;
                var rest = new ReadOnlySpan<char>(buffer, bufferPos, bufferLength - bufferPos);
                int stop = rest.IndexOfAny(QuotedStops);
                Take(rest.Slice(0, stop < 0 ? rest.Length : stop));
                if (stop >= 0) return;
            }
        }

        void Take(ReadOnlySpan<char> chars)
        {
            if (chars.Length == 0) return;
            if (consumed + chars.Length > MaxRecordLength)
            {
                // Take up to the limit, then let Next() refuse the row with the one message.
                int allowed = MaxRecordLength - consumed;
                for (int i = 0; i < allowed; i++) Append(chars[i]);
                bufferPos += allowed;
                consumed += allowed;
                Next();
            }
            if (recordLength + chars.Length > record.Length)
                Array.Resize(ref record, Math.Min(Math.Max(record.Length * 2, recordLength + chars.Length), MaxRecordLength + 1));
            chars.CopyTo(new Span<char>(record, recordLength, chars.Length));
            recordLength += chars.Length;
            consumed += chars.Length;
            bufferPos += chars.Length;
        }

        void Append(char c)
        {
            if (recordLength == record.Length)
            {
                int size = Math.Min(record.Length * 2, MaxRecordLength + 1);
                if (size <= record.Length) size = record.Length + 1;
                Array.Resize(ref record, size);
            }
            record[recordLength++] = c;
        }

        int Peek()
        {
            if (bufferPos >= bufferLength && !Fill()) return -1;
            return buffer[bufferPos];
        }

        int Next()
        {
            int c = Peek();
            if (c < 0) return -1;
            bufferPos++;
            if (++consumed > MaxRecordLength)
                throw Error(Line, "the row is longer than " + MaxRecordLength.ToString(CultureInfo.InvariantCulture)
                                  + " characters (the limit for one row; is a line break missing?)");
            return c;
        }

        /// <summary>
        /// <see cref="Next"/> outside quotes, where a line break ends the record: it is not one of the record's
        /// characters (so a record of <see cref="MaxRecordLength"/> characters is read whether it ends in LF, CRLF,
        /// CR or nothing). Line breaks inside quotes are read by <see cref="Next"/> and counted.
        /// </summary>
        int NextOutsideQuotes()
        {
            int c = Peek();
            if (c != '\n' && c != '\r') return Next();
            bufferPos++;
            return c;
        }

        bool Fill()
        {
            if (atEnd) return false;
            for (;;)
            {
                bufferLength = reader.Read(buffer, 0, buffer.Length);
                bufferPos = 0;
                if (bufferLength <= 0)
                {
                    bufferLength = 0;
                    atEnd = true;
                    return false;
                }
                if (!started)
                {
                    started = true;
                    if (buffer[0] == '\uFEFF') bufferPos = 1; // a byte-order mark the reader left in
                    if (bufferPos >= bufferLength) continue;
                }
                return true;
            }
        }

        public void Dispose()
        {
            if (!leaveOpen) reader.Dispose();
        }
    }
}
