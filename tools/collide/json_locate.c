/* collide tool: positions of values in JSON text. The scanner trusts nothing: it stops at the end
 * of the buffer and reports failure on anything it does not expect, and it skips nested values
 * with a depth counter instead of recursion, so hostile nesting cannot exhaust the stack. */
#include "json_locate.h"

#include <string.h>

static size_t skipWhitespace(const char* text, size_t length, size_t i)
{
	while (i < length && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r'))
	{
		++i;
	}
	return i;
}

/* text[i] is '"'; returns the offset just past the closing quote. */
static bool skipString(const char* text, size_t length, size_t* i)
{
	size_t j = *i + 1;
	while (j < length)
	{
		if (text[j] == '\\')
		{
			j += 2;
			continue;
		}
		if (text[j] == '"')
		{
			*i = j + 1;
			return true;
		}
		++j;
	}
	return false;
}

static bool skipValue(const char* text, size_t length, size_t* i)
{
	size_t j = *i;
	if (j >= length)
	{
		return false;
	}
	if (text[j] == '"')
	{
		return skipString(text, length, i);
	}
	if (text[j] == '{' || text[j] == '[')
	{
		long depth = 0;
		while (j < length)
		{
			char c = text[j];
			if (c == '"')
			{
				if (!skipString(text, length, &j))
				{
					return false;
				}
				continue;
			}
			if (c == '{' || c == '[')
			{
				++depth;
			}
			else if (c == '}' || c == ']')
			{
				--depth;
				if (depth == 0)
				{
					*i = j + 1;
					return true;
				}
			}
			++j;
		}
		return false;
	}
	/* number, true, false, null */
	size_t start = j;
	while (j < length && strchr(",]} \t\r\n", text[j]) == NULL)
	{
		++j;
	}
	*i = j;
	return j > start;
}

/* Compares the raw text of a key (between its quotes, escapes not decoded) with `key`. Keys with
 * escapes do not match; the caller then falls back to a coarser position. */
static bool keyEquals(const char* text, size_t start, size_t end, const char* key)
{
	size_t keyLength = strlen(key);
	return end - start == keyLength && memcmp(text + start, key, keyLength) == 0;
}

static bool stepInto(const char* text, size_t length, JsonPathStep step, size_t* i)
{
	size_t j = skipWhitespace(text, length, *i);
	if (j >= length)
	{
		return false;
	}
	if (step.key != NULL)
	{
		if (text[j] != '{')
		{
			return false;
		}
		++j;
		for (;;)
		{
			j = skipWhitespace(text, length, j);
			if (j >= length || text[j] != '"')
			{
				return false;
			}
			size_t keyStart = j + 1;
			if (!skipString(text, length, &j))
			{
				return false;
			}
			bool match = keyEquals(text, keyStart, j - 1, step.key);
			j = skipWhitespace(text, length, j);
			if (j >= length || text[j] != ':')
			{
				return false;
			}
			j = skipWhitespace(text, length, j + 1);
			if (match)
			{
				*i = j;
				return j < length;
			}
			if (!skipValue(text, length, &j))
			{
				return false;
			}
			j = skipWhitespace(text, length, j);
			if (j >= length || text[j] != ',')
			{
				return false;
			}
			++j;
		}
	}
	if (text[j] != '[' || step.index < 0)
	{
		return false;
	}
	++j;
	for (int k = 0;; ++k)
	{
		j = skipWhitespace(text, length, j);
		if (j >= length || text[j] == ']')
		{
			return false;
		}
		if (k == step.index)
		{
			*i = j;
			return true;
		}
		if (!skipValue(text, length, &j))
		{
			return false;
		}
		j = skipWhitespace(text, length, j);
		if (j >= length || text[j] != ',')
		{
			return false;
		}
		++j;
	}
}

bool jsonLocate(const char* text, size_t length, const JsonPathStep* path, int depth, size_t* offset)
{
	size_t i = 0;
	for (int k = 0; k < depth; ++k)
	{
		if (!stepInto(text, length, path[k], &i))
		{
			return false;
		}
	}
	i = skipWhitespace(text, length, i);
	if (i >= length)
	{
		return false;
	}
	*offset = i;
	return true;
}

int jsonLineOfOffset(const char* text, size_t length, size_t offset)
{
	/* LF, CRLF and a lone CR (old Mac files) each end a line. */
	int line = 1;
	for (size_t i = 0; i < offset && i < length; ++i)
	{
		if (text[i] == '\n' || (text[i] == '\r' && (i + 1 >= length || text[i + 1] != '\n')))
		{
			++line;
		}
	}
	return line;
}

/* Whether c can precede the start of a JSON value. */
static bool valueBoundary(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ':' || c == '[';
}

bool jsonCheckLexical(const char* text, size_t length, size_t* offset, const char** reason)
{
	bool inString = false;
	for (size_t i = 0; i < length; ++i)
	{
		char c = text[i];
		if (inString)
		{
			if (c == '\\' && i + 1 < length)
			{
				if (text[i + 1] == 'u' && i + 5 < length && strncmp(text + i + 2, "0000", 4) == 0)
				{
					*offset = i;
					*reason = "\\u0000 in a string (a NUL character would silently cut the string)";
					return false;
				}
				++i; /* the escaped character */
			}
			else if (c == '"')
			{
				inString = false;
			}
			continue;
		}
		if (c == '"')
		{
			inString = true;
			continue;
		}
		bool start = (c == '-' || (c >= '0' && c <= '9')) && (i == 0 || valueBoundary(text[i - 1]));
		if (start)
		{
			size_t j = c == '-' ? i + 1 : i;
			if (j + 1 < length && text[j] == '0' && text[j + 1] >= '0' && text[j + 1] <= '9')
			{
				*offset = i;
				*reason = "invalid JSON number: leading zeros";
				return false;
			}
			while (i + 1 < length && strchr("0123456789+-.eE", text[i + 1]) != NULL && text[i + 1] != 0)
			{
				++i;
			}
		}
	}
	return true;
}

int jsonMaxDepth(const char* text, size_t length, int limit, size_t* firstTooDeep)
{
	int depth = 0, maxDepth = 0;
	bool inString = false;
	for (size_t i = 0; i < length; ++i)
	{
		char c = text[i];
		if (inString)
		{
			if (c == '\\')
			{
				++i;
			}
			else if (c == '"')
			{
				inString = false;
			}
			continue;
		}
		if (c == '"')
		{
			inString = true;
		}
		else if (c == '[' || c == '{')
		{
			++depth;
			if (depth > maxDepth)
			{
				maxDepth = depth;
				if (depth == limit + 1 && firstTooDeep != NULL)
				{
					*firstTooDeep = i;
				}
			}
		}
		else if ((c == ']' || c == '}') && depth > 0)
		{
			--depth;
		}
	}
	return maxDepth;
}
