"""Numbers in a page's prose made by the tool that makes the page, and the page's tool-made block
(replace_block). A marked span

    <!-- = KEY -->text<!-- end -->

holds what the tool's resolver gives for KEY (a change with its interval and verdict, a count, a
mean); the tool replaces every span's text each time it writes the page, and a test that makes the
page again from the committed records fails on any difference. The markers do not show in the
rendered page; a number typed outside a span is one no tool answers for."""
import re

SPAN = re.compile(r"<!-- = (.+?) -->(.*?)<!-- end -->", re.S)


class UnknownKey(KeyError):
    pass


def fill(text, resolve, only=None):
    """`text` with every span's content replaced by resolve(KEY); UnknownKey names a key the resolver
    does not know (resolve raises KeyError for it). With `only`, the spans whose key begins with it
    (a page whose spans several tools fill), the others left as they are."""
    def one(m):
        key = m.group(1).strip()
        if only is not None and not key.startswith(only):
            return m.group(0)
        try:
            value = resolve(key)
        except KeyError:
            raise UnknownKey(f"the page's span <!-- = {key} --> names nothing the tool makes") from None
        return f"<!-- = {key} -->{value}<!-- end -->"
    return SPAN.sub(one, text)


def keys(text):
    """The keys of the page's spans, in order."""
    return [m.group(1).strip() for m in SPAN.finditer(text)]


def replace_block(page, block, begin, end):
    """`page` with its tool-made block, from the line `begin` to the line `end`, replaced by `block`
    (which holds both); the page's own text around it stays. A page without the block gets it at its end."""
    if begin in page and end in page:
        return page[:page.index(begin)] + block + page[page.index(end) + len(end):]
    return (page.rstrip("\n") + "\n\n" if page.strip() else "") + block + "\n"
